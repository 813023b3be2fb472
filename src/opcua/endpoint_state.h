#pragma once
// The endpoint's state, shared by its files: endpoint.cpp (connections, chunks, channels,
// dispatch, sessions), services.cpp (views, attributes, methods), subscriptions.cpp.

#include <deque>
#include <map>
#include <optional>
#include <random>
#include <vector>

#include "gdpn/opcua/endpoint.h"
#include "gdpn/opcua/status.h"

namespace gdpn::opcua::detail {

/// Binary encodings of the requests (the response's is the request's + 3).
enum Service : std::uint32_t {
  kFindServers = 422,
  kGetEndpoints = 428,
  kOpenSecureChannel = 446,
  kCloseSecureChannel = 452,
  kCreateSession = 461,
  kActivateSession = 467,
  kCloseSession = 473,
  kCancel = 479,
  kBrowse = 527,
  kBrowseNext = 533,
  kTranslateBrowsePaths = 554,
  kRegisterNodes = 560,
  kUnregisterNodes = 566,
  kRead = 631,
  kWrite = 673,
  kCall = 712,
  kCreateMonitoredItems = 751,
  kModifyMonitoredItems = 763,
  kSetMonitoringMode = 769,
  kDeleteMonitoredItems = 781,
  kCreateSubscription = 787,
  kModifySubscription = 793,
  kSetPublishingMode = 799,
  kPublish = 826,
  kRepublish = 832,
  kDeleteSubscriptions = 847,
};
inline constexpr std::uint32_t kServiceFault = 397;
inline constexpr std::uint32_t kDataChangeNotification = 811, kStatusChangeNotification = 820;
inline constexpr std::uint32_t kDataChangeFilter = 724, kEventFilter = 727, kAggregateFilter = 730;
inline constexpr std::uint32_t kAnonymousToken = 321, kUserNameToken = 324, kX509Token = 327, kIssuedToken = 940;
inline constexpr const char* kPolicyNone = "http://opcfoundation.org/UA/SecurityPolicy#None";
inline constexpr const char* kTransportProfile = "http://opcfoundation.org/UA-Profile/Transport/uatcp-uasc-uabinary";

/// Whether a data encoding asked of a Read or a monitored item is the default one: none, or
/// "Default Binary" of namespace 0 (the Value's own encoding).
inline bool defaultEncoding(const QualifiedName& q) { return q.name.empty() || (q.ns == 0 && q.name == "Default Binary"); }

/// The header every request starts with.
struct RequestHeader {
  NodeId token;                  // the session's authentication token
  std::uint32_t handle = 0;      // echoed in the response
  std::uint32_t timeout_hint = 0;  // ms, 0: none
};

/// One request being answered: where the answer goes.
struct Pending {
  ConnectionId connection = 0;
  std::uint32_t request_id = 0;  // the secure conversation's
  std::uint32_t handle = 0;      // the request header's
};

/// A monitored item.
struct MonitoredItem {
  std::uint32_t id = 0;
  std::uint32_t client_handle = 0;
  NodeId node;
  std::uint32_t attribute = 13;
  std::uint32_t mode = 2;               // 0 disabled, 1 sampling, 2 reporting
  std::uint32_t timestamps = 0;         // TimestampsToReturn: 0 source, 1 server, 2 both, 3 neither
  double sampling = 0;                  // ms of model time, revised: 0 = every step
  DateTime next_sample = 0;             // the model time it is sampled at next
  std::size_t queue_size = 1;
  bool discard_oldest = true;
  std::uint32_t trigger = 1;            // 0 status, 1 status+value, 2 status+value+timestamp
  std::optional<double> deadband;       // absolute
  std::optional<DataValue> last;        // the value last queued
  std::deque<DataValue> queue;
};

/// A subscription.
struct Subscription {
  std::uint32_t id = 0;
  std::uint64_t session = 0;
  double interval = 100;                // ms
  std::uint32_t lifetime = 300, keepalive = 10, max_notifications = 0;
  bool enabled = true;
  std::uint8_t priority = 0;
  std::uint32_t next_sequence = 1;
  std::uint32_t keepalive_count = 0, lifetime_count = 0;
  bool sent_once = false;               // the first cycle sends a keep-alive when there is nothing
  bool late = false;                    // found something to send (or a keep-alive due) and no Publish request
  Endpoint::Clock::time_point last_sent;  // when it last sent (the late one waiting longest goes first)
  Endpoint::Clock::time_point due;
  std::map<std::uint32_t, MonitoredItem> items;
  std::deque<std::pair<std::uint32_t, std::string>> retransmit;  // sequence number, encoded NotificationMessage
  std::optional<StatusCode> closing;   // expired: its StatusChangeNotification waits for a Publish, then it goes
};

/// A waiting Publish request.
struct PublishRequest {
  Pending to;
  Endpoint::Clock::time_point deadline;  // max: none
  std::vector<StatusCode> ack_results;
};

/// A session.
struct Session {
  std::uint64_t number = 0;
  NodeId id, token;
  std::string name;
  double timeout = 60000;               // ms
  Endpoint::Clock::time_point last_seen;
  Endpoint::Clock::time_point created;
  bool activated = false;
  std::uint32_t channel = 0;             // the secure channel it is bound to
  std::deque<PublishRequest> publish;
  std::map<std::string, std::pair<std::size_t, std::vector<std::string>>> continuations;  // a Browse's most per node and remaining references (encoded), by its point
  std::uint64_t next_continuation = 1;
};

/// A connection and its secure channel.
struct Connection {
  std::string peer;
  std::string in, out;
  bool hello = false;
  std::uint32_t channel = 0, token = 0;   // the newest token issued
  std::uint32_t previous_token = 0;       // the one before a renewal, taken until the new one is used
  std::uint32_t send_token = 0;           // the token the server's messages carry
  std::uint32_t send_sequence = 0, receive_sequence = 0;
  bool sequenced = false;                // receive_sequence is set
  std::uint32_t send_buffer = 8192, receive_buffer = 8192;  // negotiated: chunk sizes each way
  std::uint32_t max_send_message = 0, max_send_chunks = 0;  // the client's (0: no limit)
  // a message arriving in chunks
  std::uint32_t partial_request = 0;
  std::string partial;
  std::uint32_t partial_chunks = 0;
  bool closing = false;
  bool goodbye = false;                  // it sent CloseSecureChannel
};

/// A Call waiting for the run's steps.
struct PendingCall {
  Pending to;
  std::uint64_t due = 0;                 // the step count (asked) it waits for
  std::vector<StatusCode> status;
  std::vector<std::vector<StatusCode>> in_results;
  std::vector<std::vector<Variant>> outputs;
  std::vector<std::function<void(std::vector<Variant>&)>> complete;
};

/// The endpoint's state.
struct EndpointState {
  EndpointState(AddressSpace& s, std::string u, const ServerLimits& l, bool ro)
      : space(s), url(std::move(u)), limits(l), read_only(ro) {}
  AddressSpace& space;
  std::string url;
  ServerLimits limits;
  bool read_only = false;
  EndpointStats stats;
  std::map<ConnectionId, Connection> connections;
  ConnectionId next_connection = 1;
  std::uint32_t next_channel = 1;
  std::map<std::uint64_t, Session> sessions;
  std::uint64_t next_session = 1;
  std::map<std::uint32_t, Subscription> subscriptions;
  std::uint32_t next_subscription = 1, next_item = 1;
  std::size_t item_count = 0;             // monitored items of every subscription
  std::mt19937_64 random{std::random_device{}()};
  DateTime model_time = 0;
  bool lockstep = false;
  std::uint64_t asked = 0, taken = 0;
  std::vector<PendingCall> calls;
  Endpoint::Clock::time_point now = Endpoint::Clock::now();

  // endpoint.cpp
  void sendChunks(Connection& c, const char* type, std::uint32_t request_id, const std::string& body);
  bool error(Connection& c, StatusCode code, const std::string& reason);  // ERR, and the connection closes
  void respond(const Pending& to, std::uint32_t type, const std::string& body);  // body after the header
  // a ServiceFault; `counted`: in the faults of the run's summary (Publish's normal course is not)
  void fault(const Pending& to, StatusCode status, bool counted = true);
  void respondResults(const Pending& to, std::uint32_t type, const std::vector<StatusCode>& results);  // a status each, no diagnostics
  std::string responseHeader(std::uint32_t handle, StatusCode result = 0) const;
  Session* session(const Connection& c, const RequestHeader& h, StatusCode& why, bool must_be_active = true);
  std::string randomBytes(std::size_t n);
  void closeSession(std::uint64_t number, bool delete_subscriptions);

  // services.cpp: each answers its request (the header read), or throws DecodeError
  void browse(const Pending& to, Session& s, Decoder& d);
  void browseNext(const Pending& to, Session& s, Decoder& d);
  void translate(const Pending& to, Decoder& d);
  void registerNodes(const Pending& to, Decoder& d, bool register_them);
  void read(const Pending& to, Decoder& d);
  void write(const Pending& to, Session& s, Decoder& d);
  void call(const Pending& to, Decoder& d);
  void answerCalls();
  DataValue readValue(const NodeId& node, std::uint32_t attribute, std::uint32_t timestamps) const;

  // subscriptions.cpp
  void createSubscription(const Pending& to, Session& s, Decoder& d);
  void modifySubscription(const Pending& to, Session& s, Decoder& d);
  void setPublishingMode(const Pending& to, Session& s, Decoder& d);
  void deleteSubscriptions(const Pending& to, Session& s, Decoder& d);
  void createItems(const Pending& to, Session& s, Decoder& d);
  void modifyItems(const Pending& to, Session& s, Decoder& d);
  void setMonitoringMode(const Pending& to, Session& s, Decoder& d);
  void deleteItems(const Pending& to, Session& s, Decoder& d);
  void publish(const Pending& to, Session& s, Decoder& d, std::uint32_t timeout_hint);
  void republish(const Pending& to, Session& s, Decoder& d);
  void publishDue();
  void sampleAll();
  void sampleItem(MonitoredItem& item);
  Subscription* subscription(Session& s, std::uint32_t id);
  void deleteSubscription(std::uint32_t id);
  bool sendNotifications(Subscription& sub, Session& s);
  bool sendClosing(Subscription& sub, Session& s);  // its StatusChangeNotification, if a request waits
  std::size_t messageRoom(const Pending& to) const;  // bytes a response to `to` may take
  void sendKeepAlive(Subscription& sub, Session& s);
};

}  // namespace gdpn::opcua::detail
