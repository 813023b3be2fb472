#pragma once
/// \file
/// OPC UA's binary encoding (Part 6, 5.2): the built-in types and the encoder and decoder of
/// them. The decoder is strict and bounded: it never reads past its bytes, never allocates more
/// than the bytes could hold, and nests at most kMaxDepth deep; anything else throws
/// DecodeError with the status a server answers with.
#include <compare>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace gdpn::opcua {

/// The built-in types, numbered as on the wire (a Variant's encoding mask).
enum class BuiltinType : std::uint8_t {
  Null = 0,
  Boolean = 1,
  SByte = 2,
  Byte = 3,
  Int16 = 4,
  UInt16 = 5,
  Int32 = 6,
  UInt32 = 7,
  Int64 = 8,
  UInt64 = 9,
  Float = 10,
  Double = 11,
  String = 12,
  DateTime = 13,
  Guid = 14,
  ByteString = 15,
  XmlElement = 16,
  NodeId = 17,
  ExpandedNodeId = 18,
  StatusCode = 19,
  QualifiedName = 20,
  LocalizedText = 21,
  ExtensionObject = 22,
  DataValue = 23,
  Variant = 24,
  DiagnosticInfo = 25,
};

/// A status code: the top two bits say good (00), uncertain (01) or bad (10).
using StatusCode = std::uint32_t;

/// Time on the wire: 100 ns intervals since 1601-01-01 00:00 UTC.
using DateTime = std::int64_t;

/// A DateTime for `seconds` after 1970-01-01 00:00 UTC.
DateTime dateTimeFromUnix(double seconds);
/// The wall clock now, as a DateTime.
DateTime dateTimeNow();

/// A node's identifier: a namespace index and a number, a string, a GUID or bytes.
struct NodeId {
  /// Which kind of identifier.
  enum class Kind : std::uint8_t { Numeric, String, Guid, Opaque };
  std::uint16_t ns = 0;        ///< the namespace index
  Kind kind = Kind::Numeric;   ///< the identifier's kind
  std::uint32_t numeric = 0;   ///< a numeric identifier
  std::string text;            ///< a string identifier, or a GUID's 16 bytes, or opaque bytes

  /// `i=N` in namespace `ns`.
  static NodeId num(std::uint32_t id, std::uint16_t ns = 0) { return NodeId{ns, Kind::Numeric, id, {}}; }
  /// `s=TEXT` in namespace `ns`.
  static NodeId str(std::string id, std::uint16_t ns = 1) { return NodeId{ns, Kind::String, 0, std::move(id)}; }
  /// Whether it is the null NodeId (ns=0;i=0).
  [[nodiscard]] bool isNull() const { return ns == 0 && kind == Kind::Numeric && numeric == 0; }
  /// The standard text form: `i=85`, `ns=1;s=io/eye`, `ns=2;g=...`, `ns=3;b=base64`.
  [[nodiscard]] std::string str() const;
  /// Parses the standard text form (`ns=` optional; `i=`, `s=`, `g=`, `b=`). Null with `why`.
  static std::optional<NodeId> parse(std::string_view text, std::string& why);
  friend auto operator<=>(const NodeId&, const NodeId&) = default;
  friend bool operator==(const NodeId&, const NodeId&) = default;
};

/// A NodeId with an optional namespace URI and server index (Browse's results).
struct ExpandedNodeId {
  NodeId node;                 ///< the node
  std::string namespace_uri;   ///< "" when the index says it
  std::uint32_t server = 0;    ///< 0: this server
  friend bool operator==(const ExpandedNodeId&, const ExpandedNodeId&) = default;
};

/// A name qualified by a namespace index (a BrowseName).
struct QualifiedName {
  std::uint16_t ns = 0;   ///< the namespace index
  std::string name;       ///< the name
  friend bool operator==(const QualifiedName&, const QualifiedName&) = default;
};

/// Text with its locale (DisplayName, Description).
struct LocalizedText {
  std::string locale;  ///< "" : none
  std::string text;    ///< the text
  friend bool operator==(const LocalizedText&, const LocalizedText&) = default;
};

/// A structure carried by its encoding's NodeId: the body's bytes are decoded by who knows it.
struct ExtensionObject {
  NodeId type;                 ///< the encoding's NodeId (e.g. i=889 EUInformation's binary encoding)
  std::uint8_t encoding = 0;   ///< 0: no body, 1: binary, 2: XML
  std::string body;            ///< the body's bytes
  friend bool operator==(const ExtensionObject&, const ExtensionObject&) = default;
};

/// A value of any built-in type, a scalar or a one-dimensional array. DataValue, Variant and
/// DiagnosticInfo inside a Variant are refused by the decoder (nobody sends them to a server).
struct Variant {
  /// The scalar's storage: Boolean; the signed integers and DateTime as int64; the unsigned and
  /// StatusCode as uint64; Float and Double as double; String, ByteString, XmlElement and Guid
  /// as bytes; the rest as themselves.
  using Scalar = std::variant<std::monostate, bool, std::int64_t, std::uint64_t, double, std::string, NodeId,
                              ExpandedNodeId, QualifiedName, LocalizedText, ExtensionObject>;
  BuiltinType type = BuiltinType::Null;  ///< Null: no value
  bool is_array = false;                 ///< an array of `type`: `elements`
  Scalar scalar;                         ///< the value of a scalar
  std::vector<Variant> elements;         ///< an array's elements, each a scalar of `type`

  /// A scalar of `type` holding `value`.
  template <class T>
  static Variant of(BuiltinType type, T value) {
    Variant v;
    v.type = type;
    v.scalar = Scalar(std::move(value));
    return v;
  }
  static Variant boolean(bool b) { return of(BuiltinType::Boolean, b); }                     ///< a Boolean
  static Variant int32(std::int32_t x) { return of(BuiltinType::Int32, std::int64_t{x}); }   ///< an Int32
  static Variant uint32(std::uint32_t x) { return of(BuiltinType::UInt32, std::uint64_t{x}); }  ///< a UInt32
  static Variant dbl(double x) { return of(BuiltinType::Double, x); }                        ///< a Double
  static Variant string(std::string s) { return of(BuiltinType::String, std::move(s)); }     ///< a String
  /// An array of Strings.
  static Variant strings(const std::vector<std::string>& list);
  /// The number of a numeric or Boolean scalar as a double; nullopt for any other.
  [[nodiscard]] std::optional<double> number() const;
  /// The same type, shape and value (what a data change compares).
  friend bool operator==(const Variant&, const Variant&) = default;
};

/// A value with its status and timestamps (what Read returns and Write takes).
struct DataValue {
  std::optional<Variant> value;            ///< the value
  std::optional<StatusCode> status;        ///< absent: Good
  std::optional<DateTime> source_time;     ///< when the source had it
  std::optional<DateTime> server_time;     ///< when the server had it
};

/// What the decoder throws: the status to answer with and what was wrong.
class DecodeError : public std::runtime_error {
 public:
  /// `status` is usually BadDecodingError; `what` says where.
  DecodeError(StatusCode status, const std::string& what) : std::runtime_error(what), status_(status) {}
  /// The status to answer with.
  [[nodiscard]] StatusCode status() const { return status_; }

 private:
  StatusCode status_;
};

/// Appends values in the binary encoding to a byte string.
class Encoder {
 public:
  /// Appends to `out`.
  explicit Encoder(std::string& out) : out_(out) {}
  void u8(std::uint8_t v);                  ///< a Byte
  void u16(std::uint16_t v);                ///< a UInt16, little-endian
  void u32(std::uint32_t v);                ///< a UInt32
  void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }  ///< an Int32
  void u64(std::uint64_t v);                ///< a UInt64
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }  ///< an Int64, a DateTime
  void f32(float v);                        ///< a Float
  void f64(double v);                       ///< a Double
  void boolean(bool v) { u8(v ? 1 : 0); }   ///< a Boolean
  void string(std::string_view s);          ///< a String or ByteString: its length, then its bytes
  void nullString() { i32(-1); }            ///< a null String or ByteString
  void nodeId(const NodeId& id);            ///< a NodeId, in its shortest form
  void expandedNodeId(const ExpandedNodeId& id);  ///< an ExpandedNodeId
  void qualifiedName(const QualifiedName& q);     ///< a QualifiedName
  void localizedText(const LocalizedText& t);     ///< a LocalizedText (absent parts left out)
  void extensionObject(const ExtensionObject& e);  ///< an ExtensionObject
  void variant(const Variant& v);           ///< a Variant
  void dataValue(const DataValue& v);       ///< a DataValue
  void noDiagnostics() { u8(0); }           ///< an empty DiagnosticInfo
  /// An array's length (-1: null), before its elements.
  void length(std::size_t n) { i32(static_cast<std::int32_t>(n)); }
  /// An array of Strings.
  void strings(const std::vector<std::string>& list);
  /// An array of StatusCodes.
  void statuses(const std::vector<StatusCode>& list);
  /// Where the next byte goes (to patch a length in later).
  [[nodiscard]] std::size_t size() const { return out_.size(); }
  /// Overwrites the UInt32 at `at` (a length known only when the rest is written).
  void patchU32(std::size_t at, std::uint32_t v);

 private:
  void scalar(BuiltinType type, const Variant::Scalar& s);
  std::string& out_;
};

/// Reads values in the binary encoding from bytes, bounded by them.
class Decoder {
 public:
  /// How deep Variants and DiagnosticInfos may nest.
  static constexpr int kMaxDepth = 8;
  /// Reads `size` bytes from `data` (kept, not copied).
  Decoder(const std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}
  /// Reads `bytes` (kept, not copied).
  explicit Decoder(std::string_view bytes)
      : Decoder(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()) {}
  std::uint8_t u8();            ///< a Byte
  std::uint16_t u16();          ///< a UInt16
  std::uint32_t u32();          ///< a UInt32
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }  ///< an Int32
  std::uint64_t u64();          ///< a UInt64
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }  ///< an Int64, a DateTime
  float f32();                  ///< a Float
  double f64();                 ///< a Double
  bool boolean() { return u8() != 0; }  ///< a Boolean (any non-zero byte is true)
  /// A String or ByteString (null reads as ""); longer than `max` bytes: BadEncodingLimitsExceeded.
  std::string string(std::size_t max = 1u << 24);
  NodeId nodeId();                      ///< a NodeId
  ExpandedNodeId expandedNodeId();      ///< an ExpandedNodeId
  QualifiedName qualifiedName();        ///< a QualifiedName
  LocalizedText localizedText();        ///< a LocalizedText
  ExtensionObject extensionObject();    ///< an ExtensionObject (its body kept as bytes)
  Variant variant();                    ///< a Variant
  DataValue dataValue();                ///< a DataValue
  void skipDiagnosticInfo();            ///< a DiagnosticInfo, read and dropped
  /// An array's length: -1 (null) reads as 0; more elements than bytes left (each at least
  /// `min_element_bytes`) is a decoding error.
  std::size_t length(std::size_t min_element_bytes = 1);
  std::vector<std::string> strings();           ///< an array of Strings
  std::vector<std::uint32_t> u32s();            ///< an array of UInt32s
  /// Bytes not read yet.
  [[nodiscard]] std::size_t left() const { return static_cast<std::size_t>(end_ - p_); }
  /// The bytes not read yet, as a view.
  [[nodiscard]] std::string_view rest() const {
    return {reinterpret_cast<const char*>(p_), left()};
  }
  /// Throws unless every byte was read.
  void expectEnd() const;
  /// The fewest bytes a value of `type` takes on the wire (0 for Null): what bounds an array's
  /// length by the bytes left.
  static std::size_t minimumBytes(BuiltinType type);

 private:
  const std::uint8_t* need(std::size_t n);
  NodeId nodeIdBody(std::uint8_t form);
  Variant::Scalar scalar(BuiltinType type);
  const std::uint8_t* p_;
  const std::uint8_t* end_;
  int depth_ = 0;
};

}  // namespace gdpn::opcua
