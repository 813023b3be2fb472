// Status codes by name.

#include "gdpn/opcua/status.h"

#include <cstdio>

namespace gdpn::opcua::status {

std::string name(StatusCode code) {
  switch (code) {
    case kGood: return "Good";
    case kBadUnexpectedError: return "BadUnexpectedError";
    case kBadInternalError: return "BadInternalError";
    case kBadEncodingError: return "BadEncodingError";
    case kBadDecodingError: return "BadDecodingError";
    case kBadEncodingLimitsExceeded: return "BadEncodingLimitsExceeded";
    case kBadRequestTooLarge: return "BadRequestTooLarge";
    case kBadResponseTooLarge: return "BadResponseTooLarge";
    case kBadTimeout: return "BadTimeout";
    case kBadServiceUnsupported: return "BadServiceUnsupported";
    case kBadShutdown: return "BadShutdown";
    case kBadNothingToDo: return "BadNothingToDo";
    case kBadTooManyOperations: return "BadTooManyOperations";
    case kBadTcpMessageTypeInvalid: return "BadTcpMessageTypeInvalid";
    case kBadTcpSecureChannelUnknown: return "BadTcpSecureChannelUnknown";
    case kBadTcpMessageTooLarge: return "BadTcpMessageTooLarge";
    case kBadTcpNotEnoughResources: return "BadTcpNotEnoughResources";
    case kBadTcpInternalError: return "BadTcpInternalError";
    case kBadTcpEndpointUrlInvalid: return "BadTcpEndpointUrlInvalid";
    case kBadTcpServerTooBusy: return "BadTcpServerTooBusy";
    case kBadSecureChannelIdInvalid: return "BadSecureChannelIdInvalid";
    case kBadSecurityPolicyRejected: return "BadSecurityPolicyRejected";
    case kBadSecurityModeRejected: return "BadSecurityModeRejected";
    case kBadTooManySessions: return "BadTooManySessions";
    case kBadSessionIdInvalid: return "BadSessionIdInvalid";
    case kBadSessionClosed: return "BadSessionClosed";
    case kBadSessionNotActivated: return "BadSessionNotActivated";
    case kBadSubscriptionIdInvalid: return "BadSubscriptionIdInvalid";
    case kBadNodeIdInvalid: return "BadNodeIdInvalid";
    case kBadNodeIdUnknown: return "BadNodeIdUnknown";
    case kBadAttributeIdInvalid: return "BadAttributeIdInvalid";
    case kBadIndexRangeInvalid: return "BadIndexRangeInvalid";
    case kBadIndexRangeNoData: return "BadIndexRangeNoData";
    case kBadDataEncodingInvalid: return "BadDataEncodingInvalid";
    case kBadDataEncodingUnsupported: return "BadDataEncodingUnsupported";
    case kBadNotReadable: return "BadNotReadable";
    case kBadNotWritable: return "BadNotWritable";
    case kBadOutOfRange: return "BadOutOfRange";
    case kBadNotSupported: return "BadNotSupported";
    case kBadNotFound: return "BadNotFound";
    case kBadMonitoringModeInvalid: return "BadMonitoringModeInvalid";
    case kBadMonitoredItemIdInvalid: return "BadMonitoredItemIdInvalid";
    case kBadMonitoredItemFilterInvalid: return "BadMonitoredItemFilterInvalid";
    case kBadMonitoredItemFilterUnsupported: return "BadMonitoredItemFilterUnsupported";
    case kBadFilterNotAllowed: return "BadFilterNotAllowed";
    case kBadContinuationPointInvalid: return "BadContinuationPointInvalid";
    case kBadNoContinuationPoints: return "BadNoContinuationPoints";
    case kBadReferenceTypeIdInvalid: return "BadReferenceTypeIdInvalid";
    case kBadBrowseDirectionInvalid: return "BadBrowseDirectionInvalid";
    case kBadNodeNotInView: return "BadNodeNotInView";
    case kBadViewIdUnknown: return "BadViewIdUnknown";
    case kBadIdentityTokenInvalid: return "BadIdentityTokenInvalid";
    case kBadIdentityTokenRejected: return "BadIdentityTokenRejected";
    case kBadRequestHeaderInvalid: return "BadRequestHeaderInvalid";
    case kBadTimestampsToReturnInvalid: return "BadTimestampsToReturnInvalid";
    case kBadTypeMismatch: return "BadTypeMismatch";
    case kBadMethodInvalid: return "BadMethodInvalid";
    case kBadArgumentsMissing: return "BadArgumentsMissing";
    case kBadTooManyArguments: return "BadTooManyArguments";
    case kBadTooManySubscriptions: return "BadTooManySubscriptions";
    case kBadTooManyPublishRequests: return "BadTooManyPublishRequests";
    case kBadNoSubscription: return "BadNoSubscription";
    case kBadSequenceNumberUnknown: return "BadSequenceNumberUnknown";
    case kBadMessageNotAvailable: return "BadMessageNotAvailable";
    case kBadInvalidArgument: return "BadInvalidArgument";
    case kBadInvalidState: return "BadInvalidState";
    case kBadNotExecutable: return "BadNotExecutable";
    case kBadNoMatch: return "BadNoMatch";
    case kBadBrowseNameInvalid: return "BadBrowseNameInvalid";
    case kBadTooManyMonitoredItems: return "BadTooManyMonitoredItems";
    case kBadDeadbandFilterInvalid: return "BadDeadbandFilterInvalid";
    case kBadWriteNotSupported: return "BadWriteNotSupported";
    case kBadUserAccessDenied: return "BadUserAccessDenied";
    case kBadMaxAgeInvalid: return "BadMaxAgeInvalid";
    case kBadConnectionClosed: return "BadConnectionClosed";
    case kBadCommunicationError: return "BadCommunicationError";
    case kBadNoCommunication: return "BadNoCommunication";
    case kBadSequenceNumberInvalid: return "BadSequenceNumberInvalid";
    case kBadServerHalted: return "BadServerHalted";
    case kBadRequestCancelledByClient: return "BadRequestCancelledByClient";
    default: break;
  }
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%08X", code);
  return hex;
}

}  // namespace gdpn::opcua::status
