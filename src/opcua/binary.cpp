// OPC UA's binary encoding: built-in types written and read, little-endian, bounded.

#include "gdpn/opcua/binary.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "gdpn/opcua/status.h"

namespace gdpn::opcua {

namespace {

// 100 ns intervals from 1601-01-01 to 1970-01-01
constexpr std::int64_t kUnixEpoch = 116444736000000000;

[[noreturn]] void fail(const std::string& what) { throw DecodeError(status::kBadDecodingError, what); }

constexpr char kBase64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64(std::string_view bytes) {
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const auto v = (std::uint32_t{static_cast<std::uint8_t>(bytes[i])} << 16) |
                   (std::uint32_t{static_cast<std::uint8_t>(bytes[i + 1])} << 8) | static_cast<std::uint8_t>(bytes[i + 2]);
    for (int k = 3; k >= 0; --k) out += kBase64[(v >> (6 * k)) & 63];
  }
  if (i < bytes.size()) {
    std::uint32_t v = std::uint32_t{static_cast<std::uint8_t>(bytes[i])} << 16;
    if (i + 1 < bytes.size()) v |= std::uint32_t{static_cast<std::uint8_t>(bytes[i + 1])} << 8;
    out += kBase64[(v >> 18) & 63];
    out += kBase64[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kBase64[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::optional<std::string> unbase64(std::string_view text) {
  std::string out;
  std::uint32_t acc = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    const char* at = std::strchr(kBase64, c);
    if (c == '\0' || !at) return std::nullopt;
    acc = (acc << 6) | static_cast<std::uint32_t>(at - kBase64);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((acc >> bits) & 0xFF);
    }
  }
  return out;
}

// a GUID's 16 bytes as text: Data1-Data2-Data3-Data4[0..1]-Data4[2..7]
std::string guidText(const std::string& b) {
  char s[40];
  auto u = [&b](std::size_t i) { return static_cast<unsigned>(static_cast<std::uint8_t>(b[i])); };
  std::snprintf(s, sizeof s, "%08X-%04X-%04X-%02X%02X-%02X%02X%02X%02X%02X%02X",
                u(0) | u(1) << 8 | u(2) << 16 | u(3) << 24, u(4) | u(5) << 8, u(6) | u(7) << 8, u(8), u(9), u(10), u(11),
                u(12), u(13), u(14), u(15));
  return s;
}

std::optional<std::string> guidBytes(std::string_view t) {
  if (t.size() != 36 || t[8] != '-' || t[13] != '-' || t[18] != '-' || t[23] != '-') return std::nullopt;
  std::string hex;
  for (const char c : t) {
    if (c == '-') continue;
    if (!std::isxdigit(static_cast<unsigned char>(c))) return std::nullopt;
    hex += c;
  }
  auto byte = [&hex](std::size_t i) { return static_cast<char>(std::stoul(hex.substr(2 * i, 2), nullptr, 16)); };
  // Data1, Data2 and Data3 are little-endian on the wire
  return std::string{byte(3), byte(2), byte(1), byte(0), byte(5), byte(4), byte(7), byte(6),
                     byte(8), byte(9), byte(10), byte(11), byte(12), byte(13), byte(14), byte(15)};
}

}  // namespace

DateTime dateTimeFromUnix(double seconds) { return kUnixEpoch + std::llround(seconds * 1e7); }

DateTime dateTimeNow() {
  const auto since = std::chrono::system_clock::now().time_since_epoch();
  return kUnixEpoch + std::chrono::duration_cast<std::chrono::nanoseconds>(since).count() / 100;
}

std::string NodeId::str() const {
  std::string out = ns == 0 ? "" : "ns=" + std::to_string(ns) + ";";
  switch (kind) {
    case Kind::Numeric: return out + "i=" + std::to_string(numeric);
    case Kind::String: return out + "s=" + text;
    case Kind::Guid: return out + "g=" + (text.size() == 16 ? guidText(text) : std::string("?"));
    case Kind::Opaque: return out + "b=" + base64(text);
  }
  return out;
}

std::optional<NodeId> NodeId::parse(std::string_view text, std::string& why) {
  NodeId id;
  std::string_view rest = text;
  if (rest.starts_with("ns=")) {
    const auto semi = rest.find(';');
    const auto digits = rest.substr(3, semi == std::string_view::npos ? 0 : semi - 3);
    unsigned long n = 0;
    if (semi == std::string_view::npos || digits.empty() || digits.size() > 5 ||
        digits.find_first_not_of("0123456789") != std::string_view::npos || (n = std::stoul(std::string(digits))) > 65535) {
      why = "'" + std::string(text) + "': the namespace is ns=INDEX; with an index from 0 to 65535";
      return std::nullopt;
    }
    id.ns = static_cast<std::uint16_t>(n);
    rest = rest.substr(semi + 1);
  }
  if (rest.size() < 2 || rest[1] != '=') {
    why = "'" + std::string(text) + "' is no NodeId: write [ns=INDEX;]i=NUMBER, s=STRING, g=GUID or b=BASE64";
    return std::nullopt;
  }
  const std::string_view value = rest.substr(2);
  switch (rest[0]) {
    case 'i': {
      unsigned long long n = 0;
      if (value.empty() || value.size() > 10 || value.find_first_not_of("0123456789") != std::string_view::npos ||
          (n = std::stoull(std::string(value))) > 0xFFFFFFFFull) {
        why = "'" + std::string(text) + "': i= takes a number from 0 to 4294967295";
        return std::nullopt;
      }
      id.kind = Kind::Numeric;
      id.numeric = static_cast<std::uint32_t>(n);
      return id;
    }
    case 's':
      if (value.empty()) {
        why = "'" + std::string(text) + "': s= takes a non-empty string";
        return std::nullopt;
      }
      id.kind = Kind::String;
      id.text = value;
      return id;
    case 'g':
      if (auto b = guidBytes(value)) {
        id.kind = Kind::Guid;
        id.text = *b;
        return id;
      }
      why = "'" + std::string(text) + "': g= takes a GUID as 01234567-89AB-CDEF-0123-456789ABCDEF";
      return std::nullopt;
    case 'b':
      if (auto b = unbase64(value)) {
        id.kind = Kind::Opaque;
        id.text = *b;
        return id;
      }
      why = "'" + std::string(text) + "': b= takes base64";
      return std::nullopt;
    default: break;
  }
  why = "'" + std::string(text) + "' is no NodeId: write [ns=INDEX;]i=NUMBER, s=STRING, g=GUID or b=BASE64";
  return std::nullopt;
}

Variant Variant::strings(const std::vector<std::string>& list) {
  Variant v;
  v.type = BuiltinType::String;
  v.is_array = true;
  for (const auto& s : list) v.elements.push_back(string(s));
  return v;
}

std::optional<double> Variant::number() const {
  if (is_array) return std::nullopt;
  switch (type) {
    case BuiltinType::Boolean: return std::get<bool>(scalar) ? 1.0 : 0.0;
    case BuiltinType::SByte:
    case BuiltinType::Int16:
    case BuiltinType::Int32:
    case BuiltinType::Int64: return static_cast<double>(std::get<std::int64_t>(scalar));
    case BuiltinType::Byte:
    case BuiltinType::UInt16:
    case BuiltinType::UInt32:
    case BuiltinType::UInt64: return static_cast<double>(std::get<std::uint64_t>(scalar));
    case BuiltinType::Float:
    case BuiltinType::Double: return std::get<double>(scalar);
    case BuiltinType::Null:
    case BuiltinType::String:
    case BuiltinType::DateTime:
    case BuiltinType::Guid:
    case BuiltinType::ByteString:
    case BuiltinType::XmlElement:
    case BuiltinType::NodeId:
    case BuiltinType::ExpandedNodeId:
    case BuiltinType::StatusCode:
    case BuiltinType::QualifiedName:
    case BuiltinType::LocalizedText:
    case BuiltinType::ExtensionObject:
    case BuiltinType::DataValue:
    case BuiltinType::Variant:
    case BuiltinType::DiagnosticInfo: return std::nullopt;
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------------------------
// Encoder

void Encoder::u8(std::uint8_t v) { out_ += static_cast<char>(v); }
void Encoder::u16(std::uint16_t v) {
  u8(static_cast<std::uint8_t>(v));
  u8(static_cast<std::uint8_t>(v >> 8));
}
void Encoder::u32(std::uint32_t v) {
  for (int k = 0; k < 4; ++k) u8(static_cast<std::uint8_t>(v >> (8 * k)));
}
void Encoder::u64(std::uint64_t v) {
  for (int k = 0; k < 8; ++k) u8(static_cast<std::uint8_t>(v >> (8 * k)));
}
void Encoder::f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }
void Encoder::f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }

void Encoder::string(std::string_view s) {
  i32(static_cast<std::int32_t>(s.size()));
  out_.append(s);
}

void Encoder::patchU32(std::size_t at, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out_[at + static_cast<std::size_t>(k)] = static_cast<char>(v >> (8 * k));
}

void Encoder::nodeId(const NodeId& id) {
  switch (id.kind) {
    case NodeId::Kind::Numeric:
      if (id.ns == 0 && id.numeric <= 0xFF) {
        u8(0);  // two-byte
        u8(static_cast<std::uint8_t>(id.numeric));
      } else if (id.ns <= 0xFF && id.numeric <= 0xFFFF) {
        u8(1);  // four-byte
        u8(static_cast<std::uint8_t>(id.ns));
        u16(static_cast<std::uint16_t>(id.numeric));
      } else {
        u8(2);
        u16(id.ns);
        u32(id.numeric);
      }
      return;
    case NodeId::Kind::String:
      u8(3);
      u16(id.ns);
      string(id.text);
      return;
    case NodeId::Kind::Guid:
      u8(4);
      u16(id.ns);
      out_.append(id.text.size() == 16 ? id.text : std::string(16, '\0'));
      return;
    case NodeId::Kind::Opaque:
      u8(5);
      u16(id.ns);
      string(id.text);
      return;
  }
}

void Encoder::expandedNodeId(const ExpandedNodeId& id) {
  const std::size_t at = out_.size();
  nodeId(id.node);
  if (!id.namespace_uri.empty()) {
    out_[at] = static_cast<char>(out_[at] | 0x80);
    string(id.namespace_uri);
  }
  if (id.server != 0) {
    out_[at] = static_cast<char>(out_[at] | 0x40);
    u32(id.server);
  }
}

void Encoder::qualifiedName(const QualifiedName& q) {
  u16(q.ns);
  if (q.name.empty()) {
    nullString();  // the null name: what "no name" is on the wire (a data encoding left default)
  } else {
    string(q.name);
  }
}

void Encoder::localizedText(const LocalizedText& t) {
  u8(static_cast<std::uint8_t>((t.locale.empty() ? 0 : 1) | (t.text.empty() ? 0 : 2)));
  if (!t.locale.empty()) string(t.locale);
  if (!t.text.empty()) string(t.text);
}

void Encoder::extensionObject(const ExtensionObject& e) {
  nodeId(e.type);
  u8(e.encoding);
  if (e.encoding != 0) string(e.body);
}

void Encoder::scalar(BuiltinType type, const Variant::Scalar& s) {
  switch (type) {
    case BuiltinType::Null: return;
    case BuiltinType::Boolean: return boolean(std::get<bool>(s));
    case BuiltinType::SByte: return u8(static_cast<std::uint8_t>(std::get<std::int64_t>(s)));
    case BuiltinType::Byte: return u8(static_cast<std::uint8_t>(std::get<std::uint64_t>(s)));
    case BuiltinType::Int16: return u16(static_cast<std::uint16_t>(std::get<std::int64_t>(s)));
    case BuiltinType::UInt16: return u16(static_cast<std::uint16_t>(std::get<std::uint64_t>(s)));
    case BuiltinType::Int32: return i32(static_cast<std::int32_t>(std::get<std::int64_t>(s)));
    case BuiltinType::UInt32:
    case BuiltinType::StatusCode: return u32(static_cast<std::uint32_t>(std::get<std::uint64_t>(s)));
    case BuiltinType::Int64:
    case BuiltinType::DateTime: return i64(std::get<std::int64_t>(s));
    case BuiltinType::UInt64: return u64(std::get<std::uint64_t>(s));
    case BuiltinType::Float: return f32(static_cast<float>(std::get<double>(s)));
    case BuiltinType::Double: return f64(std::get<double>(s));
    case BuiltinType::String:
    case BuiltinType::ByteString:
    case BuiltinType::XmlElement: return string(std::get<std::string>(s));
    case BuiltinType::Guid: {
      const auto& g = std::get<std::string>(s);
      out_.append(g.size() == 16 ? g : std::string(16, '\0'));
      return;
    }
    case BuiltinType::NodeId: return nodeId(std::get<NodeId>(s));
    case BuiltinType::ExpandedNodeId: return expandedNodeId(std::get<ExpandedNodeId>(s));
    case BuiltinType::QualifiedName: return qualifiedName(std::get<QualifiedName>(s));
    case BuiltinType::LocalizedText: return localizedText(std::get<LocalizedText>(s));
    case BuiltinType::ExtensionObject: return extensionObject(std::get<ExtensionObject>(s));
    case BuiltinType::DataValue:
    case BuiltinType::Variant:
    case BuiltinType::DiagnosticInfo: return;  // never made by gdpn
  }
}

void Encoder::variant(const Variant& v) {
  if (v.type == BuiltinType::Null) return u8(0);
  u8(static_cast<std::uint8_t>(static_cast<std::uint8_t>(v.type) | (v.is_array ? 0x80 : 0)));
  if (!v.is_array) return scalar(v.type, v.scalar);
  length(v.elements.size());
  for (const auto& e : v.elements) scalar(v.type, e.scalar);
}

void Encoder::dataValue(const DataValue& v) {
  u8(static_cast<std::uint8_t>((v.value ? 1 : 0) | (v.status ? 2 : 0) | (v.source_time ? 4 : 0) | (v.server_time ? 8 : 0)));
  if (v.value) variant(*v.value);
  if (v.status) u32(*v.status);
  if (v.source_time) i64(*v.source_time);
  if (v.server_time) i64(*v.server_time);
}

void Encoder::strings(const std::vector<std::string>& list) {
  length(list.size());
  for (const auto& s : list) string(s);
}

void Encoder::statuses(const std::vector<StatusCode>& list) {
  length(list.size());
  for (const auto s : list) u32(s);
}

// ---------------------------------------------------------------------------------------------
// Decoder

std::size_t Decoder::minimumBytes(BuiltinType type) {
  switch (type) {
    case BuiltinType::Null: return 0;
    case BuiltinType::Boolean:
    case BuiltinType::SByte:
    case BuiltinType::Byte:
    case BuiltinType::LocalizedText:
    case BuiltinType::DataValue:
    case BuiltinType::Variant:
    case BuiltinType::DiagnosticInfo: return 1;
    case BuiltinType::Int16:
    case BuiltinType::UInt16:
    case BuiltinType::NodeId:
    case BuiltinType::ExpandedNodeId: return 2;
    case BuiltinType::ExtensionObject: return 3;
    case BuiltinType::Int32:
    case BuiltinType::UInt32:
    case BuiltinType::Float:
    case BuiltinType::StatusCode:
    case BuiltinType::String:
    case BuiltinType::ByteString:
    case BuiltinType::XmlElement: return 4;
    case BuiltinType::QualifiedName: return 6;
    case BuiltinType::Int64:
    case BuiltinType::UInt64:
    case BuiltinType::Double:
    case BuiltinType::DateTime: return 8;
    case BuiltinType::Guid: return 16;
  }
  return 1;
}

const std::uint8_t* Decoder::need(std::size_t n) {
  if (left() < n) fail("the message ends inside a value (" + std::to_string(n) + " bytes wanted, " + std::to_string(left()) + " left)");
  const auto* at = p_;
  p_ += n;
  return at;
}

std::uint8_t Decoder::u8() { return *need(1); }
std::uint16_t Decoder::u16() {
  const auto* b = need(2);
  return static_cast<std::uint16_t>(b[0] | b[1] << 8);
}
std::uint32_t Decoder::u32() {
  const auto* b = need(4);
  return std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 | std::uint32_t{b[2]} << 16 | std::uint32_t{b[3]} << 24;
}
std::uint64_t Decoder::u64() {
  const std::uint64_t lo = u32();
  return lo | std::uint64_t{u32()} << 32;
}
float Decoder::f32() { return std::bit_cast<float>(u32()); }
double Decoder::f64() { return std::bit_cast<double>(u64()); }

std::string Decoder::string(std::size_t max) {
  const std::int32_t n = i32();
  if (n < 0) return {};
  const auto size = static_cast<std::size_t>(n);
  if (size > max) throw DecodeError(status::kBadEncodingLimitsExceeded, "a string of " + std::to_string(size) + " bytes, more than " + std::to_string(max));
  const auto* b = need(size);
  return {reinterpret_cast<const char*>(b), size};
}

std::size_t Decoder::length(std::size_t min_element_bytes) {
  const std::int32_t n = i32();
  if (n < 0) return 0;
  const auto size = static_cast<std::size_t>(n);
  if (size > left() / std::max<std::size_t>(min_element_bytes, 1)) {
    fail("an array of " + std::to_string(size) + " elements in " + std::to_string(left()) + " bytes");
  }
  return size;
}

NodeId Decoder::nodeId() {
  const std::uint8_t form = u8();
  if ((form & 0xC0) != 0) fail("a NodeId with the flags of an ExpandedNodeId");
  return nodeIdBody(form);
}

NodeId Decoder::nodeIdBody(std::uint8_t form) {
  NodeId id;
  switch (form & 0x3F) {
    case 0: id.numeric = u8(); break;
    case 1:
      id.ns = u8();
      id.numeric = u16();
      break;
    case 2:
      id.ns = u16();
      id.numeric = u32();
      break;
    case 3:
      id.ns = u16();
      id.kind = NodeId::Kind::String;
      id.text = string(4096);
      break;
    case 4: {
      id.ns = u16();
      id.kind = NodeId::Kind::Guid;
      const auto* b = need(16);
      id.text.assign(reinterpret_cast<const char*>(b), 16);
      break;
    }
    case 5:
      id.ns = u16();
      id.kind = NodeId::Kind::Opaque;
      id.text = string(4096);
      break;
    default: fail("a NodeId of unknown encoding " + std::to_string(form & 0x3F));
  }
  return id;
}

ExpandedNodeId Decoder::expandedNodeId() {
  const std::uint8_t form = u8();
  ExpandedNodeId out;
  out.node = nodeIdBody(form);
  if (form & 0x80) out.namespace_uri = string(4096);
  if (form & 0x40) out.server = u32();
  return out;
}

QualifiedName Decoder::qualifiedName() {
  QualifiedName q;
  q.ns = u16();
  q.name = string(4096);
  return q;
}

LocalizedText Decoder::localizedText() {
  LocalizedText t;
  const std::uint8_t mask = u8();
  if (mask & 1) t.locale = string(256);
  if (mask & 2) t.text = string();
  return t;
}

ExtensionObject Decoder::extensionObject() {
  ExtensionObject e;
  e.type = nodeId();
  e.encoding = u8();
  if (e.encoding > 2) fail("an ExtensionObject of unknown encoding " + std::to_string(e.encoding));
  if (e.encoding != 0) e.body = string();
  return e;
}

Variant::Scalar Decoder::scalar(BuiltinType type) {
  switch (type) {
    case BuiltinType::Null: return std::monostate{};
    case BuiltinType::Boolean: return boolean();
    case BuiltinType::SByte: return std::int64_t{static_cast<std::int8_t>(u8())};
    case BuiltinType::Byte: return std::uint64_t{u8()};
    case BuiltinType::Int16: return std::int64_t{static_cast<std::int16_t>(u16())};
    case BuiltinType::UInt16: return std::uint64_t{u16()};
    case BuiltinType::Int32: return std::int64_t{i32()};
    case BuiltinType::UInt32:
    case BuiltinType::StatusCode: return std::uint64_t{u32()};
    case BuiltinType::Int64:
    case BuiltinType::DateTime: return i64();
    case BuiltinType::UInt64: return u64();
    case BuiltinType::Float: return static_cast<double>(f32());
    case BuiltinType::Double: return f64();
    case BuiltinType::String:
    case BuiltinType::ByteString:
    case BuiltinType::XmlElement: return string();
    case BuiltinType::Guid: {
      const auto* b = need(16);
      return std::string(reinterpret_cast<const char*>(b), 16);
    }
    case BuiltinType::NodeId: return nodeId();
    case BuiltinType::ExpandedNodeId: return expandedNodeId();
    case BuiltinType::QualifiedName: return qualifiedName();
    case BuiltinType::LocalizedText: return localizedText();
    case BuiltinType::ExtensionObject: return extensionObject();
    case BuiltinType::DataValue:
    case BuiltinType::Variant:
    case BuiltinType::DiagnosticInfo: break;
  }
  throw DecodeError(status::kBadDecodingError, "a Variant holding a DataValue, Variant or DiagnosticInfo (not taken)");
}

Variant Decoder::variant() {
  Variant v;
  const std::uint8_t mask = u8();
  const std::uint8_t type = mask & 0x3F;
  if (type > static_cast<std::uint8_t>(BuiltinType::DiagnosticInfo)) fail("a Variant of unknown type " + std::to_string(type));
  v.type = static_cast<BuiltinType>(type);
  if (!(mask & 0x80)) {
    if (mask & 0x40) fail("a scalar Variant with array dimensions");
    v.scalar = scalar(v.type);
    return v;
  }
  v.is_array = true;
  if (v.type == BuiltinType::Null) {
    if (i32() > 0) fail("an array of Null (elements of no bytes)");
    return v;
  }
  const std::size_t n = length(minimumBytes(v.type));
  v.elements.reserve(n);
  for (std::size_t i = 0; i < n; ++i) v.elements.push_back(Variant{v.type, false, scalar(v.type), {}});
  if (mask & 0x40) {
    // dimensions: gdpn serves one-dimensional arrays only; their product must be the length
    const std::size_t dims = length(4);
    std::uint64_t product = 1;
    for (std::size_t i = 0; i < dims; ++i) product *= static_cast<std::uint64_t>(std::max<std::int32_t>(i32(), 0));
    if (dims != 1 || product != n) throw DecodeError(status::kBadDecodingError, "a multi-dimensional array (not taken)");
  }
  return v;
}

DataValue Decoder::dataValue() {
  DataValue v;
  const std::uint8_t mask = u8();
  if (mask & 1) v.value = variant();
  if (mask & 2) v.status = u32();
  if (mask & 4) v.source_time = i64();
  if (mask & 0x10) (void)u16();  // source picoseconds
  if (mask & 8) v.server_time = i64();
  if (mask & 0x20) (void)u16();  // server picoseconds
  return v;
}

void Decoder::skipDiagnosticInfo() {
  if (++depth_ > kMaxDepth) fail("DiagnosticInfos nested deeper than " + std::to_string(kMaxDepth));
  const std::uint8_t mask = u8();
  for (int bit = 0; bit < 4; ++bit) {
    if (mask & (1 << bit)) (void)i32();  // symbolic id, namespace, localized text, locale
  }
  if (mask & 0x10) (void)string();  // additional info
  if (mask & 0x20) (void)u32();     // inner status code
  if (mask & 0x40) skipDiagnosticInfo();
  --depth_;
}

std::vector<std::string> Decoder::strings() {
  std::vector<std::string> out(length(4));
  for (auto& s : out) s = string();
  return out;
}

std::vector<std::uint32_t> Decoder::u32s() {
  std::vector<std::uint32_t> out(length(4));
  for (auto& v : out) v = u32();
  return out;
}

void Decoder::expectEnd() const {
  if (left() != 0) fail(std::to_string(left()) + " bytes after the end of the message");
}

}  // namespace gdpn::opcua
