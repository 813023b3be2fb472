#pragma once
/// \file
/// The status codes gdpn's OPC UA server and client answer with or understand (Part 4, 7.39; Part 6, A.2).
#include <cstdint>
#include <string>

#include "gdpn/opcua/binary.h"

namespace gdpn::opcua::status {

inline constexpr StatusCode kGood = 0x00000000u;  ///< Good
inline constexpr StatusCode kBadUnexpectedError = 0x80010000u;  ///< BadUnexpectedError
inline constexpr StatusCode kBadInternalError = 0x80020000u;  ///< BadInternalError
inline constexpr StatusCode kBadEncodingError = 0x80060000u;  ///< BadEncodingError
inline constexpr StatusCode kBadDecodingError = 0x80070000u;  ///< BadDecodingError
inline constexpr StatusCode kBadEncodingLimitsExceeded = 0x80080000u;  ///< BadEncodingLimitsExceeded
inline constexpr StatusCode kBadRequestTooLarge = 0x80B80000u;  ///< BadRequestTooLarge
inline constexpr StatusCode kBadResponseTooLarge = 0x80B90000u;  ///< BadResponseTooLarge
inline constexpr StatusCode kBadTimeout = 0x800A0000u;  ///< BadTimeout
inline constexpr StatusCode kBadServiceUnsupported = 0x800B0000u;  ///< BadServiceUnsupported
inline constexpr StatusCode kBadShutdown = 0x800C0000u;  ///< BadShutdown
inline constexpr StatusCode kBadNothingToDo = 0x800F0000u;  ///< BadNothingToDo
inline constexpr StatusCode kBadTooManyOperations = 0x80100000u;  ///< BadTooManyOperations
inline constexpr StatusCode kBadTcpMessageTypeInvalid = 0x807E0000u;  ///< BadTcpMessageTypeInvalid
inline constexpr StatusCode kBadTcpSecureChannelUnknown = 0x807F0000u;  ///< BadTcpSecureChannelUnknown
inline constexpr StatusCode kBadTcpMessageTooLarge = 0x80800000u;  ///< BadTcpMessageTooLarge
inline constexpr StatusCode kBadTcpNotEnoughResources = 0x80810000u;  ///< BadTcpNotEnoughResources
inline constexpr StatusCode kBadTcpInternalError = 0x80820000u;  ///< BadTcpInternalError
inline constexpr StatusCode kBadTcpEndpointUrlInvalid = 0x80830000u;  ///< BadTcpEndpointUrlInvalid
inline constexpr StatusCode kBadTcpServerTooBusy = 0x807D0000u;  ///< BadTcpServerTooBusy
inline constexpr StatusCode kBadSecureChannelIdInvalid = 0x80220000u;  ///< BadSecureChannelIdInvalid
inline constexpr StatusCode kBadSecurityPolicyRejected = 0x80550000u;  ///< BadSecurityPolicyRejected
inline constexpr StatusCode kBadSecurityModeRejected = 0x80540000u;  ///< BadSecurityModeRejected
inline constexpr StatusCode kBadTooManySessions = 0x80560000u;  ///< BadTooManySessions
inline constexpr StatusCode kBadSessionIdInvalid = 0x80250000u;  ///< BadSessionIdInvalid
inline constexpr StatusCode kBadSessionClosed = 0x80260000u;  ///< BadSessionClosed
inline constexpr StatusCode kBadSessionNotActivated = 0x80270000u;  ///< BadSessionNotActivated
inline constexpr StatusCode kBadSubscriptionIdInvalid = 0x80280000u;  ///< BadSubscriptionIdInvalid
inline constexpr StatusCode kBadNodeIdInvalid = 0x80330000u;  ///< BadNodeIdInvalid
inline constexpr StatusCode kBadNodeIdUnknown = 0x80340000u;  ///< BadNodeIdUnknown
inline constexpr StatusCode kBadAttributeIdInvalid = 0x80350000u;  ///< BadAttributeIdInvalid
inline constexpr StatusCode kBadIndexRangeInvalid = 0x80360000u;  ///< BadIndexRangeInvalid
inline constexpr StatusCode kBadIndexRangeNoData = 0x80370000u;  ///< BadIndexRangeNoData
inline constexpr StatusCode kBadDataEncodingInvalid = 0x80380000u;  ///< BadDataEncodingInvalid
inline constexpr StatusCode kBadDataEncodingUnsupported = 0x80390000u;  ///< BadDataEncodingUnsupported
inline constexpr StatusCode kBadNotReadable = 0x803A0000u;  ///< BadNotReadable
inline constexpr StatusCode kBadNotWritable = 0x803B0000u;  ///< BadNotWritable
inline constexpr StatusCode kBadOutOfRange = 0x803C0000u;  ///< BadOutOfRange
inline constexpr StatusCode kBadNotSupported = 0x803D0000u;  ///< BadNotSupported
inline constexpr StatusCode kBadNotFound = 0x803E0000u;  ///< BadNotFound
inline constexpr StatusCode kBadMonitoringModeInvalid = 0x80410000u;  ///< BadMonitoringModeInvalid
inline constexpr StatusCode kBadMonitoredItemIdInvalid = 0x80420000u;  ///< BadMonitoredItemIdInvalid
inline constexpr StatusCode kBadMonitoredItemFilterInvalid = 0x80430000u;  ///< BadMonitoredItemFilterInvalid
inline constexpr StatusCode kBadMonitoredItemFilterUnsupported = 0x80440000u;  ///< BadMonitoredItemFilterUnsupported
inline constexpr StatusCode kBadFilterNotAllowed = 0x80450000u;  ///< BadFilterNotAllowed
inline constexpr StatusCode kBadContinuationPointInvalid = 0x804A0000u;  ///< BadContinuationPointInvalid
inline constexpr StatusCode kBadNoContinuationPoints = 0x804B0000u;  ///< BadNoContinuationPoints
inline constexpr StatusCode kBadReferenceTypeIdInvalid = 0x804C0000u;  ///< BadReferenceTypeIdInvalid
inline constexpr StatusCode kBadBrowseDirectionInvalid = 0x804D0000u;  ///< BadBrowseDirectionInvalid
inline constexpr StatusCode kBadNodeNotInView = 0x804E0000u;  ///< BadNodeNotInView
inline constexpr StatusCode kBadViewIdUnknown = 0x806B0000u;  ///< BadViewIdUnknown
inline constexpr StatusCode kBadIdentityTokenInvalid = 0x80200000u;  ///< BadIdentityTokenInvalid
inline constexpr StatusCode kBadIdentityTokenRejected = 0x80210000u;  ///< BadIdentityTokenRejected
inline constexpr StatusCode kBadRequestHeaderInvalid = 0x802A0000u;  ///< BadRequestHeaderInvalid
inline constexpr StatusCode kBadTimestampsToReturnInvalid = 0x802B0000u;  ///< BadTimestampsToReturnInvalid
inline constexpr StatusCode kBadTypeMismatch = 0x80740000u;  ///< BadTypeMismatch
inline constexpr StatusCode kBadMethodInvalid = 0x80750000u;  ///< BadMethodInvalid
inline constexpr StatusCode kBadArgumentsMissing = 0x80760000u;  ///< BadArgumentsMissing
inline constexpr StatusCode kBadTooManyArguments = 0x80E50000u;  ///< BadTooManyArguments
inline constexpr StatusCode kBadTooManySubscriptions = 0x80770000u;  ///< BadTooManySubscriptions
inline constexpr StatusCode kBadTooManyPublishRequests = 0x80780000u;  ///< BadTooManyPublishRequests
inline constexpr StatusCode kBadNoSubscription = 0x80790000u;  ///< BadNoSubscription
inline constexpr StatusCode kBadSequenceNumberUnknown = 0x807A0000u;  ///< BadSequenceNumberUnknown
inline constexpr StatusCode kBadMessageNotAvailable = 0x807B0000u;  ///< BadMessageNotAvailable
inline constexpr StatusCode kBadInvalidArgument = 0x80AB0000u;  ///< BadInvalidArgument
inline constexpr StatusCode kBadInvalidState = 0x80AF0000u;  ///< BadInvalidState
inline constexpr StatusCode kBadNotExecutable = 0x81110000u;  ///< BadNotExecutable
inline constexpr StatusCode kBadNoMatch = 0x806F0000u;  ///< BadNoMatch
inline constexpr StatusCode kBadBrowseNameInvalid = 0x80600000u;  ///< BadBrowseNameInvalid
inline constexpr StatusCode kBadTooManyMonitoredItems = 0x80DB0000u;  ///< BadTooManyMonitoredItems
inline constexpr StatusCode kBadDeadbandFilterInvalid = 0x808E0000u;  ///< BadDeadbandFilterInvalid
inline constexpr StatusCode kBadWriteNotSupported = 0x80730000u;  ///< BadWriteNotSupported
inline constexpr StatusCode kBadUserAccessDenied = 0x801F0000u;  ///< BadUserAccessDenied
inline constexpr StatusCode kBadMaxAgeInvalid = 0x80700000u;  ///< BadMaxAgeInvalid
inline constexpr StatusCode kBadConnectionClosed = 0x80AE0000u;  ///< BadConnectionClosed
inline constexpr StatusCode kBadCommunicationError = 0x80050000u;  ///< BadCommunicationError
inline constexpr StatusCode kBadNoCommunication = 0x80310000u;  ///< BadNoCommunication
inline constexpr StatusCode kBadSequenceNumberInvalid = 0x80880000u;  ///< BadSequenceNumberInvalid
inline constexpr StatusCode kBadServerHalted = 0x800E0000u;  ///< BadServerHalted
inline constexpr StatusCode kBadRequestCancelledByClient = 0x802C0000u;  ///< BadRequestCancelledByClient

/// The code's name (`BadNotWritable`), or its number in hex when it is none of the above.
std::string name(StatusCode code);

/// Whether the code is bad (its top bit set).
inline bool isBad(StatusCode code) { return (code & 0x80000000u) != 0; }

}  // namespace gdpn::opcua::status
