// A build without SocketCAN (IG_WITH_CAN=OFF): --can is refused.
#include <stdexcept>

#include "session/live/serve_plugins.h"

namespace ig::session {

std::unique_ptr<ExtraPoseSource> make_can_source(const CanSourceSettings&) {
  throw std::invalid_argument("--can: this ig was built without SocketCAN (IG_WITH_CAN=OFF)");
}

}  // namespace ig::session
