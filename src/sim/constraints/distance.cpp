#include "sim/constraints/distance.h"

#include <cmath>

namespace systole::sim {

double solve_distance(double* xa, double* xb, const double* da, const double* db, double wa, double wb,
                      double rest, double alpha_tilde, double gamma) {
  const double w = wa + wb;
  if (w == 0) return 0;
  const double dx = xb[0] - xa[0], dy = xb[1] - xa[1], dz = xb[2] - xa[2];
  const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
  if (len < 1e-12) return 0;  // Direction undefined; neighbours will separate them.
  const double nx = dx / len, ny = dy / len, nz = dz / len;
  const double c = len - rest;
  // Relative motion along the constraint this substep: what the damping term resists.
  const double rel = nx * (db[0] - da[0]) + ny * (db[1] - da[1]) + nz * (db[2] - da[2]);
  const double dlambda = (-c - gamma * rel) / ((1.0 + gamma) * w + alpha_tilde);
  xa[0] -= wa * dlambda * nx;
  xa[1] -= wa * dlambda * ny;
  xa[2] -= wa * dlambda * nz;
  xb[0] += wb * dlambda * nx;
  xb[1] += wb * dlambda * ny;
  xb[2] += wb * dlambda * nz;
  return dlambda;
}

}  // namespace systole::sim
