#pragma once
/// \file
/// Modbus TCP requests taken apart: where a frame ends in a stream of bytes, and what a frame
/// asks (function, table, addresses, values), or which exception it earns. Pure functions of
/// bytes: no sockets, no libmodbus, no model.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gdpn/model/io.h"

namespace gdpn::modbus {

/// Bytes of the MBAP header before the function code: transaction (2), protocol (2),
/// length (2), unit (1).
inline constexpr std::size_t kHeaderBytes = 7;
/// The longest frame Modbus TCP allows: the header and a 253-byte PDU, in bytes.
inline constexpr std::size_t kMaxFrameBytes = kHeaderBytes + 253;

/// The length in bytes of the frame that `stream` starts with: 0 while more bytes are needed;
/// -1 when the bytes are no Modbus TCP (a protocol id other than 0, a length field below 2
/// or above 254): the connection can no longer be read frame by frame and is closed.
std::ptrdiff_t frameLength(std::span<const std::uint8_t> stream);

/// The function codes gdpn serves.
enum class Function : std::uint8_t {
  ReadCoils = 1,
  ReadDiscreteInputs = 2,
  ReadHoldingRegisters = 3,
  ReadInputRegisters = 4,
  WriteSingleCoil = 5,
  WriteSingleRegister = 6,
  WriteMultipleCoils = 15,
  WriteMultipleRegisters = 16,
};

/// One request: what a whole frame asks.
struct Request {
  std::uint16_t transaction = 0;  ///< the client's transaction id, echoed in the reply
  std::uint8_t unit = 0;          ///< the unit id (any is served)
  std::uint8_t function = 0;      ///< the function code as sent
  model::IoTable table = model::IoTable::Coils;  ///< the table it reads or writes
  bool write = false;             ///< whether it writes (functions 5, 6, 15, 16)
  std::uint16_t address = 0;      ///< its first address
  std::uint16_t count = 0;        ///< how many addresses (1 for the single writes)
  std::vector<bool> bits;         ///< coils to write
  std::vector<std::uint16_t> words;  ///< holding registers to write
  /// The exception the request earns by its form alone: IllegalFunction for a function not
  /// served, IllegalValue for a wrong quantity, byte count or length, or a single coil's value
  /// other than 0xFF00 and 0x0000, IllegalAddress for a range past 65535. None: well formed.
  model::IoError error = model::IoError::None;
};

/// Takes apart one whole frame (`frameLength` bytes of it).
Request decodeRequest(std::span<const std::uint8_t> frame);

}  // namespace gdpn::modbus
