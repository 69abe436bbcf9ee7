#pragma once

namespace cairn::systems {

/// What a port carries: an Eigen::VectorXd of a declared size, or any C++ type behind AbstractValue.
enum class PortDataType { kVector, kAbstract };

}  // namespace cairn::systems
