// Modbus TCP requests taken apart (the Modbus Application Protocol v1.1b3, section 6, and
// Modbus Messaging on TCP/IP v1.0b, section 3.1.3).

#include "gdpn/modbus/request.h"

namespace gdpn::modbus {

namespace {

std::uint16_t word(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::uint16_t>((b[at] << 8) | b[at + 1]);
}

// the limits on a quantity, per function (Modbus Application Protocol, section 6)
constexpr std::uint16_t kMaxReadBits = 2000;
constexpr std::uint16_t kMaxReadWords = 125;
constexpr std::uint16_t kMaxWriteBits = 1968;
constexpr std::uint16_t kMaxWriteWords = 123;

}  // namespace

std::ptrdiff_t frameLength(std::span<const std::uint8_t> stream) {
  if (stream.size() < 6) return 0;
  if (word(stream, 2) != 0) return -1;
  const std::uint16_t length = word(stream, 4);  // the unit id and the PDU
  if (length < 2 || length > 254) return -1;
  const std::size_t total = 6 + std::size_t{length};
  return stream.size() < total ? 0 : static_cast<std::ptrdiff_t>(total);
}

Request decodeRequest(std::span<const std::uint8_t> frame) {
  using model::IoError;
  using model::IoTable;
  Request r;
  r.transaction = word(frame, 0);
  r.unit = frame[6];
  r.function = frame[7];
  const std::span<const std::uint8_t> pdu = frame.subspan(kHeaderBytes);  // function code first
  const auto bad = [&](IoError e) {
    r.error = e;
    r.bits.clear();
    r.words.clear();
    return r;
  };
  std::uint16_t max = 0;
  switch (static_cast<Function>(r.function)) {
    case Function::ReadCoils: r.table = IoTable::Coils; max = kMaxReadBits; break;
    case Function::ReadDiscreteInputs: r.table = IoTable::DiscreteInputs; max = kMaxReadBits; break;
    case Function::ReadHoldingRegisters: r.table = IoTable::HoldingRegisters; max = kMaxReadWords; break;
    case Function::ReadInputRegisters: r.table = IoTable::InputRegisters; max = kMaxReadWords; break;
    case Function::WriteSingleCoil:
    case Function::WriteMultipleCoils: r.table = IoTable::Coils; r.write = true; max = kMaxWriteBits; break;
    case Function::WriteSingleRegister:
    case Function::WriteMultipleRegisters:
      r.table = IoTable::HoldingRegisters;
      r.write = true;
      max = kMaxWriteWords;
      break;
    default: return bad(IoError::IllegalFunction);
  }
  const auto f = static_cast<Function>(r.function);
  const bool single = f == Function::WriteSingleCoil || f == Function::WriteSingleRegister;
  const bool multiple = f == Function::WriteMultipleCoils || f == Function::WriteMultipleRegisters;
  // function, address and a quantity (or a value) come first
  if (pdu.size() < 5) return bad(IoError::IllegalValue);
  r.address = word(pdu, 1);
  if (single) {
    if (pdu.size() != 5) return bad(IoError::IllegalValue);
    r.count = 1;
    const std::uint16_t v = word(pdu, 3);
    if (f == Function::WriteSingleCoil) {
      if (v != 0xFF00 && v != 0x0000) return bad(IoError::IllegalValue);
      r.bits.push_back(v == 0xFF00);
    } else {
      r.words.push_back(v);
    }
    return r;
  }
  r.count = word(pdu, 3);
  if (r.count < 1 || r.count > max) return bad(IoError::IllegalValue);
  if (!multiple) {
    if (pdu.size() != 5) return bad(IoError::IllegalValue);
  } else {
    const bool bits = f == Function::WriteMultipleCoils;
    const std::size_t bytes = bits ? (std::size_t{r.count} + 7) / 8 : 2 * std::size_t{r.count};
    if (pdu.size() < 6 || pdu[5] != bytes || pdu.size() != 6 + bytes) return bad(IoError::IllegalValue);
    for (std::size_t k = 0; k < r.count; ++k) {
      if (bits) {
        r.bits.push_back(((pdu[6 + k / 8] >> (k % 8)) & 1) != 0);
      } else {
        r.words.push_back(word(pdu, 6 + 2 * k));
      }
    }
  }
  if (std::uint32_t{r.address} + r.count > 65536) return bad(IoError::IllegalAddress);
  return r;
}

}  // namespace gdpn::modbus
