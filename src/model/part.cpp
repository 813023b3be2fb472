// Parts: the names of their I/O's directions and signals.

#include "gdpn/model/part.h"

namespace gdpn::model {

const char* ioDirectionName(IoDirection direction) {
  switch (direction) {
    case IoDirection::Input: return "input";
    case IoDirection::Output: return "output";
  }
  return "?";
}

const char* ioSignalName(IoSignal signal) {
  switch (signal) {
    case IoSignal::Digital: return "digital";
    case IoSignal::Analog: return "analog";
  }
  return "?";
}

}  // namespace gdpn::model
