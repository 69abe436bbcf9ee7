#pragma once

#include <string>

namespace cairn::cli {

/// The folder holding Cairn's data (robots/, models/): `share/cairn` of the install prefix when the running
/// `cairn` is an installed one (found from the executable's own path, so a moved prefix still works), otherwise
/// the source tree's data/ folder the build was configured from. An installed command must not depend on the
/// source tree still being there.
std::string DataDirectory();

}  // namespace cairn::cli
