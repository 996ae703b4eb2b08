#pragma once
// sim::State: everything that changes while a body moves. Stepping is a pure function of
// (Model, State), so snapshots, restarts and determinism tests are plain copies.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "sim/model.h"

namespace systole::sim {

struct ImplicitCache;  // sim/implicit_euler.h

/// The implicit solver's reusable system matrix (pattern built once), value-slot table and
/// CG solver: empty until the first implicit step builds it. Copying deep-copies it, so a
/// copied State steps on its own with the same results.
class ImplicitScratch {
 public:
  ImplicitScratch();
  ~ImplicitScratch();
  ImplicitScratch(const ImplicitScratch& other);
  ImplicitScratch& operator=(const ImplicitScratch& other);
  ImplicitScratch(ImplicitScratch&& other) noexcept;
  ImplicitScratch& operator=(ImplicitScratch&& other) noexcept;

  ImplicitCache* get() const { return cache_.get(); }
  void reset(std::unique_ptr<ImplicitCache> cache);

 private:
  std::unique_ptr<ImplicitCache> cache_;
};

struct State {
  double time_s = 0;                 ///< unit: s
  Eigen::Matrix3Xd x;                ///< Positions. unit: m
  Eigen::Matrix3Xd v;                ///< Velocities. unit: m/s
  Eigen::VectorXd spring_lambda;     ///< XPBD multipliers of the last substep; force = lambda / h^2. unit: N s^2
  double volume_lambda = 0;          ///< unit: N s^2 / m^2
  Eigen::Matrix3Xd attachment_lambda;  ///< Per particle, the attachments' multipliers of the last substep; force = lambda / h^2. unit: N s^2

  // Scratch reused by every step so stepping never allocates.
  Eigen::Matrix3Xd x_prev;           ///< Positions at the start of the substep. unit: m
  Eigen::VectorXd region_contraction;  ///< amplitude * phi per region at the current substep. unit: 1
  Eigen::Matrix3Xd volume_gradient;  ///< dV/dx per particle. unit: m^2
  Eigen::Matrix3Xd attachment_target;  ///< Attachment targets at the current substep. unit: m
  Eigen::Matrix3Xd force;            ///< Force per particle (explicit and implicit solvers). unit: N
  ImplicitScratch implicit;          ///< Matrix and solver of the implicit solver (built lazily).
};

/// The body at rest at t = 0.
State initial_state(const Model& model);

}  // namespace systole::sim
