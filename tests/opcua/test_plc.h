#pragma once
// A small PLC stand-in for the client's tests: gdpn's own OPC UA server on a free port, served
// by a thread of the test.

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "gdpn/opcua/server.h"
#include "gdpn/opcua/status.h"

namespace gdpn::opcua {

/// gdpn's server with PLC/Eye (Boolean) and PLC/Height (Int16), written by the client; PLC/Belt
/// (Boolean) and PLC/Speed (Int32), set by the test; PLC/Limit (Double, read-only).
class TestPlc {
 public:
  TestPlc() : space_({"http://opcfoundation.org/UA/", "urn:test:plc"}, "urn:test:plc", "test plc", "1") {
    const NodeId plc = NodeId::str("PLC");
    space_.addObject(NodeId::num(id::kObjectsFolder), plc, 1, "PLC", id::kBaseObjectType);
    Node& eye = space_.addVariable(plc, NodeId::str("Eye"), 1, "Eye", 1);
    eye.read = [this] { return Variant::boolean(eye_.load()); };
    eye.write = [this](const Variant& v) {
      eye_ = std::get<bool>(v.scalar);
      return status::kGood;
    };
    Node& height = space_.addVariable(plc, NodeId::str("Height"), 1, "Height", 4);
    height.numeric = true;
    height.read = [this] { return Variant::of(BuiltinType::Int16, std::int64_t{height_.load()}); };
    height.write = [this](const Variant& v) {
      height_ = std::get<std::int64_t>(v.scalar);
      return status::kGood;
    };
    Node& belt = space_.addVariable(plc, NodeId::str("Belt"), 1, "Belt", 1);
    belt.read = [this] { return Variant::boolean(belt_.load()); };
    Node& speed = space_.addVariable(plc, NodeId::str("Speed"), 1, "Speed", 6);
    speed.read = [this] { return Variant::int32(speed_.load()); };
    Node& limit = space_.addVariable(plc, NodeId::str("Limit"), 1, "Limit", 11);
    limit.value = Variant::dbl(2.5);
    ServerOptions options;
    options.port = 0;
    std::string why;
    server_ = Server::listen(space_, options, why);
    EXPECT_TRUE(server_) << why;
    if (!server_) return;
    url_ = server_->url();
    thread_ = std::thread([this] {
      double t = 0;
      while (!stop_) {
        server_->round(2'000'000);
        t += 0.002;
        server_->endpoint().sample(t);
        server_->flush();
      }
    });
  }
  ~TestPlc() { shutdown(); }
  /// Stops serving and closes every connection.
  void shutdown() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    server_.reset();
  }
  const std::string& url() const { return url_; }
  std::atomic<bool> eye_{false}, belt_{false};
  std::atomic<std::int64_t> height_{0};
  std::atomic<std::int32_t> speed_{0};

 private:
  AddressSpace space_;
  std::unique_ptr<Server> server_;
  std::string url_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

}  // namespace gdpn::opcua
