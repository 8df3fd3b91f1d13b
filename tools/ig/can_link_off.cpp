// A build without SocketCAN (IG_WITH_CAN=OFF): --can is refused.
#include "cli_args.h"
#include "serve_plugins.h"

namespace ig::app {

std::unique_ptr<ExtraPoseSource> make_can_source(const CanSourceSettings&) {
  throw UsageError("--can: this ig was built without SocketCAN (IG_WITH_CAN=OFF)");
}

}  // namespace ig::app
