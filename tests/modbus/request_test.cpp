// Modbus TCP requests taken apart: frames cut from a stream, each function's fields, and the
// exception each malformed request earns (Modbus Application Protocol v1.1b3, section 6).

#include <gtest/gtest.h>

#include <vector>

#include "gdpn/modbus/request.h"

namespace gdpn::modbus {
namespace {

using Bytes = std::vector<std::uint8_t>;
using model::IoError;
using model::IoTable;

/// The MBAP header (transaction 0x1234, protocol 0, length, unit 1) before `pdu`.
Bytes frame(const Bytes& pdu, std::uint16_t protocol = 0) {
  const auto length = static_cast<std::uint16_t>(pdu.size() + 1);
  // filled byte by byte: GCC 12 warns wrongly (array-bounds) on inserting into a short vector
  Bytes out(7 + pdu.size());
  const std::uint8_t head[] = {0x12, 0x34, static_cast<std::uint8_t>(protocol >> 8), static_cast<std::uint8_t>(protocol & 0xff),
                               static_cast<std::uint8_t>(length >> 8), static_cast<std::uint8_t>(length & 0xff), 0x01};
  for (std::size_t k = 0; k < 7; ++k) out[k] = head[k];
  for (std::size_t k = 0; k < pdu.size(); ++k) out[7 + k] = pdu[k];
  return out;
}

Request decode(const Bytes& pdu) { return decodeRequest(frame(pdu)); }

TEST(ModbusFrame, AWholeFrameIsItsHeaderAndLength) {
  const Bytes f = frame({0x03, 0x00, 0x00, 0x00, 0x02});
  EXPECT_EQ(frameLength(f), 12);
  Bytes two = f;
  two.insert(two.end(), f.begin(), f.end());
  EXPECT_EQ(frameLength(two), 12);  // the first of two pipelined frames
}

TEST(ModbusFrame, APartOfAFrameWaitsForTheRest) {
  const Bytes f = frame({0x03, 0x00, 0x00, 0x00, 0x02});
  for (std::size_t n = 0; n < f.size(); ++n) {
    EXPECT_EQ(frameLength({f.data(), n}), 0) << n << " bytes";
  }
}

TEST(ModbusFrame, BytesThatAreNoModbusTcpCloseTheConnection) {
  EXPECT_EQ(frameLength(frame({0x03, 0x00, 0x00, 0x00, 0x02}, 1)), -1);  // protocol id 1
  const Bytes http = {'G', 'E', 'T', ' ', '/', ' ', 'H', 'T', 'T', 'P'};
  EXPECT_EQ(frameLength(http), -1);
  EXPECT_EQ(frameLength(Bytes{0, 1, 0, 0, 0, 1, 1}), -1);       // a length of 1: no function code
  EXPECT_EQ(frameLength(Bytes{0, 1, 0, 0, 0x00, 0xff}), -1);    // 255: past the longest PDU
  EXPECT_EQ(frameLength(Bytes{0, 1, 0, 0, 0x00, 0xfe}), 0);     // 254: the longest, still coming
}

TEST(ModbusRequest, ReadsNameTheirTableAddressAndCount) {
  const struct {
    std::uint8_t function;
    IoTable table;
  } cases[] = {{1, IoTable::Coils}, {2, IoTable::DiscreteInputs}, {3, IoTable::HoldingRegisters}, {4, IoTable::InputRegisters}};
  for (const auto& c : cases) {
    const Request r = decode({c.function, 0x01, 0x02, 0x00, 0x07});
    EXPECT_EQ(r.error, IoError::None) << int(c.function);
    EXPECT_EQ(r.transaction, 0x1234);
    EXPECT_EQ(r.table, c.table);
    EXPECT_FALSE(r.write);
    EXPECT_EQ(r.address, 0x0102);
    EXPECT_EQ(r.count, 7);
  }
}

TEST(ModbusRequest, WritesCarryTheirValues) {
  Request r = decode({5, 0x00, 0x03, 0xFF, 0x00});
  EXPECT_EQ(r.error, IoError::None);
  EXPECT_TRUE(r.write);
  EXPECT_EQ(r.table, IoTable::Coils);
  EXPECT_EQ(r.bits, std::vector<bool>{true});
  r = decode({6, 0x00, 0x04, 0xAB, 0xCD});
  EXPECT_EQ(r.table, IoTable::HoldingRegisters);
  EXPECT_EQ(r.words, std::vector<std::uint16_t>{0xABCD});
  // coils packed from the lowest bit of the first byte: 1, 0, 1, 1, 0, 0, 0, 0, 1, 1
  r = decode({15, 0x00, 0x10, 0x00, 0x0A, 0x02, 0x0D, 0x03});
  EXPECT_EQ(r.error, IoError::None);
  EXPECT_EQ(r.address, 16);
  EXPECT_EQ(r.bits, (std::vector<bool>{true, false, true, true, false, false, false, false, true, true}));
  r = decode({16, 0x00, 0x00, 0x00, 0x02, 0x04, 0x00, 0x01, 0xFF, 0xFF});
  EXPECT_EQ(r.words, (std::vector<std::uint16_t>{1, 0xFFFF}));
}

TEST(ModbusRequest, EachMalformedRequestEarnsItsException) {
  EXPECT_EQ(decode({0x2B, 0x0E, 0x01, 0x00}).error, IoError::IllegalFunction);  // device identification
  EXPECT_EQ(decode({0x17, 0, 0, 0, 1, 0, 0, 0, 1, 2, 0, 0}).error, IoError::IllegalFunction);
  EXPECT_EQ(decode({0x81, 0, 0, 0, 1}).error, IoError::IllegalFunction);
  EXPECT_EQ(decode({1, 0, 0, 0, 0}).error, IoError::IllegalValue);                  // 0 coils
  EXPECT_EQ(decode({1, 0, 0, 0x07, 0xD1}).error, IoError::IllegalValue);            // 2001 coils
  EXPECT_EQ(decode({1, 0, 0, 0x07, 0xD0}).error, IoError::None);                    // 2000
  EXPECT_EQ(decode({3, 0, 0, 0, 126}).error, IoError::IllegalValue);                // 126 registers
  EXPECT_EQ(decode({4, 0, 0, 0, 125}).error, IoError::None);
  EXPECT_EQ(decode({3, 0xFF, 0xFF, 0, 2}).error, IoError::IllegalAddress);          // 65535 and 65536
  EXPECT_EQ(decode({3, 0xFF, 0xFF, 0, 1}).error, IoError::None);
  EXPECT_EQ(decode({5, 0, 0, 0x12, 0x34}).error, IoError::IllegalValue);            // a coil is 0xFF00 or 0
  EXPECT_EQ(decode({3, 0, 0}).error, IoError::IllegalValue);                        // cut short
  EXPECT_EQ(decode({3, 0, 0, 0, 1, 0}).error, IoError::IllegalValue);               // a byte too many
  EXPECT_EQ(decode({15, 0, 0, 0, 10, 1, 0xFF}).error, IoError::IllegalValue);       // 10 coils in 1 byte
  EXPECT_EQ(decode({16, 0, 0, 0, 2, 4, 0, 1}).error, IoError::IllegalValue);        // 4 bytes said, 2 sent
  EXPECT_EQ(decode({16, 0, 0, 0, 124, 248}).error, IoError::IllegalValue);          // 124 registers
  EXPECT_EQ(decode({7}).error, IoError::IllegalFunction);                           // read exception status
  const Request refused = decode({16, 0, 0, 0, 2, 4, 0, 1});
  EXPECT_TRUE(refused.words.empty());
}

}  // namespace
}  // namespace gdpn::modbus
