#include "mesh/procedural.h"

#include "common/error.h"
#include "mesh/procedural/organs.h"

namespace systole::mesh {

std::vector<std::string> procedural_organs() { return {"heart", "anatomical_heart", "lungs", "kidney", "liver", "diaphragm", "chest_wall"}; }

OrganMesh generate_organ(const std::string& name, int detail) {
  if (detail < 1 || detail > 6) {
    throw Error(ExitCode::kDataError, "procedural organ '" + name + "': detail must be 1 to 6, got " +
                                          std::to_string(detail));
  }
  if (name == "heart") return procedural::heart(detail);
  if (name == "anatomical_heart") return procedural::anatomical_heart(detail);
  if (name == "lungs") return procedural::lungs(detail);
  if (name == "kidney") return procedural::kidney(detail);
  if (name == "liver") return procedural::liver(detail);
  if (name == "diaphragm") return procedural::diaphragm(detail);
  if (name == "chest_wall") return procedural::chest_wall(detail);
  std::string known;
  for (const std::string& organ : procedural_organs()) known += (known.empty() ? "" : ", ") + organ;
  throw Error(ExitCode::kDataError, "unknown procedural organ '" + name + "' (known: " + known + ")");
}

namespace procedural {

int target_triangles(int detail) { return 1200 << (detail - 1); }

}  // namespace procedural
}  // namespace systole::mesh
