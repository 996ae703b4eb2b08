#pragma once
// sim::State: everything that changes while a body moves. Stepping is a pure function of
// (Model, State), so snapshots, restarts and determinism tests are plain copies.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "sim/model.h"

namespace systole::sim {

/// What a solver keeps between steps - a system matrix, its factorization, the history a
/// multistep method needs - built by its first step. Polymorphic so State need not know
/// each solver's cache, and cloneable so a copied State steps on its own with the same
/// results.
struct SolverCache {
  virtual ~SolverCache() = default;
  virtual std::unique_ptr<SolverCache> clone() const = 0;
};

/// Owns a SolverCache; copying deep-copies it.
class SolverScratch {
 public:
  SolverScratch() = default;
  SolverScratch(const SolverScratch& other) : cache_(other.cache_ ? other.cache_->clone() : nullptr) {}
  SolverScratch& operator=(const SolverScratch& other) {
    if (this != &other) cache_ = other.cache_ ? other.cache_->clone() : nullptr;
    return *this;
  }
  SolverScratch(SolverScratch&&) noexcept = default;
  SolverScratch& operator=(SolverScratch&&) noexcept = default;

  /// The cache if it is a T, else null (another solver stepped this state before).
  template <class T>
  T* get() const {
    return dynamic_cast<T*>(cache_.get());
  }
  void reset(std::unique_ptr<SolverCache> cache) { cache_ = std::move(cache); }

 private:
  std::unique_ptr<SolverCache> cache_;
};

struct State {
  double time_s = 0;                 ///< unit: s
  Eigen::Matrix3Xd x;                ///< Positions. unit: m
  Eigen::Matrix3Xd v;                ///< Velocities. unit: m/s
  Eigen::VectorXd spring_lambda;     ///< XPBD multipliers of the last substep; force = lambda / h^2. unit: N s^2
  double volume_lambda = 0;          ///< unit: N s^2 / m^2
  Eigen::Matrix3Xd attachment_lambda;  ///< Per particle, the attachments' multipliers of the last substep; force = lambda / h^2. unit: N s^2
  std::vector<ChamberState> chambers;  ///< Per model.circulation chamber: its phase, volume and pressure.

  // Scratch reused by every step so stepping never allocates.
  Eigen::Matrix3Xd x_prev;           ///< Positions at the start of the substep. unit: m
  Eigen::VectorXd region_contraction;  ///< amplitude * phi per region at the current substep. unit: 1
  Eigen::Matrix3Xd volume_gradient;  ///< dV/dx per particle. unit: m^2
  Eigen::Matrix3Xd attachment_target;  ///< Attachment targets at the current substep. unit: m
  /// Per particle, what its embedded attachment points ask of it and their summed weights
  /// (sim::solve_embedded_attachments). unit: N s^2, 1
  Eigen::Matrix3Xd attachment_pull;
  Eigen::VectorXd attachment_hold;
  Eigen::Matrix3Xd force;            ///< Force per particle (explicit and implicit solvers). unit: N
  SolverScratch solver_cache;        ///< The implicit or projective solver's matrices (built lazily).
};

/// The body at rest at t = 0.
State initial_state(const Model& model);

}  // namespace systole::sim
