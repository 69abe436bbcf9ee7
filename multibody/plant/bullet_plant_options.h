#pragma once

namespace cairn::multibody {

/// How a BulletPlant steps. The defaults are those of a 1 kHz position-controlled humanoid simulation (thesis
/// 2.3.3 used ODE at 1 ms).
struct BulletPlantOptions {
  /// Fixed integration step (s): in (0, kMaxTimeStep]. Bullet integrates semi-implicitly (velocities first).
  double time_step = 1e-3;
  /// Create collision shapes and contacts. Without them the plant is a pure articulated-body integrator (used to
  /// cross-check the dynamics against ForwardDynamics); with them every collision shape must be a primitive.
  bool contacts = true;
  /// Iterations of Bullet's sequential-impulse contact solver per step (1 .. kMaxSolverIterations).
  int solver_iterations = 100;
  /// Largest time step accepted (s): above it PD control and contacts are no longer resolved at 1 kHz quality.
  static constexpr double kMaxTimeStep = 0.01;
  /// Largest number of solver iterations accepted.
  static constexpr int kMaxSolverIterations = 10000;
};

}  // namespace cairn::multibody
