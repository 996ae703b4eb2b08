#include "train/tuned_scene.h"

#include <sstream>

#include "scene/write.h"

namespace systole::train {

std::string tuned_scene_yaml(const scene::Scene& scene, const std::vector<OrganTuning>& tunings,
                             const std::filesystem::path& output) {
  std::vector<scene::OrganRegions> changes;
  std::ostringstream note;
  note.precision(3);
  for (const scene::Organ& organ : scene.organs) {
    for (const OrganTuning& tuning : tunings) {
      if (tuning.organ != organ.name) continue;
      changes.push_back({tuning.organ, tuning.regions});
      note << "# systole tune: organ '" << tuning.organ << "' RMS error " << tuning.before.rms_pct_of_motion
           << " % (fitted) -> " << tuning.after.rms_pct_of_motion << " % (tuned) of the target's motion, " << tuning.generations
           << " generations" << (tuning.kept_written ? "; the drives as written, the search found none closer" : "") << ".\n";
    }
  }
  return scene::scene_yaml_with_regions(scene, changes, output, note.str());
}

}  // namespace systole::train
