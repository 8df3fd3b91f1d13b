// A build without Modbus (IG_WITH_MODBUS=OFF): --modbus is refused.
#include "cli_args.h"
#include "serve_plugins.h"

namespace ig::app {

void check_modbus_endpoint(const std::string&) {
  throw UsageError("--modbus: this ig was built without Modbus (IG_WITH_MODBUS=OFF)");
}

std::unique_ptr<ControlSurface> make_modbus_surface(const std::string&, session::ScenarioRunner&, io::LatencyMode, bool) {
  throw UsageError("--modbus: this ig was built without Modbus (IG_WITH_MODBUS=OFF)");
}

}  // namespace ig::app
