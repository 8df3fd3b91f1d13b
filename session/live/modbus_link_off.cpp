// A build without Modbus (IG_WITH_MODBUS=OFF): --modbus is refused.
#include <stdexcept>

#include "session/live/serve_plugins.h"

namespace ig::session {

void check_modbus_endpoint(const std::string&) {
  throw std::invalid_argument("--modbus: this ig was built without Modbus (IG_WITH_MODBUS=OFF)");
}

std::unique_ptr<ControlSurface> make_modbus_surface(const std::string&, const std::vector<std::string>&, ScenarioRunner&,
                                                    io::LatencyMode, bool) {
  throw std::invalid_argument("--modbus: this ig was built without Modbus (IG_WITH_MODBUS=OFF)");
}

}  // namespace ig::session
