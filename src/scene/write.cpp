#include "scene/write.h"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>

#include "common/error.h"
#include "scene/overrides.h"
#include "scene/tree.h"

namespace systole::scene {

namespace {

/// A quantity as the scene format writes it: "1.2 Hz", "0.16 s". Full precision, so the
/// written scene plays exactly what was tuned.
std::string quantity(double value, const char* unit) {
  std::ostringstream s;
  s.precision(10);
  s << value << " " << unit;
  return s.str();
}

std::string plain(double value) {
  std::ostringstream s;
  s.precision(10);
  s << value;
  return s.str();
}

YAML::Node drive_node(const Drive& d) {
  YAML::Node n(YAML::NodeType::Map);
  n.SetStyle(YAML::EmitterStyle::Flow);
  const char* waveforms[] = {"none", "sine", "fourier", "cardiac", "breathing", "samples"};
  n["waveform"] = waveforms[static_cast<int>(d.waveform)];
  if (d.waveform == Waveform::kNone) return n;
  n["rate"] = quantity(d.rate_hz, "Hz");
  n["amplitude"] = plain(d.amplitude);
  if (d.phase_rad != 0) n["phase"] = quantity(d.phase_rad, "rad");
  if (d.delay_s != 0) n["delay"] = quantity(d.delay_s, "s");
  if (d.waveform == Waveform::kCardiac) n["systolic_fraction"] = plain(d.systolic_fraction);
  if (d.waveform == Waveform::kCardiac && d.peak_fraction != 0.5) n["peak_fraction"] = plain(d.peak_fraction);
  if (d.waveform == Waveform::kBreathing) n["inhale_fraction"] = plain(d.inhale_fraction);
  if (d.waveform == Waveform::kFourier) {
    YAML::Node list(YAML::NodeType::Sequence);
    for (const auto& h : d.harmonics) {
      YAML::Node item(YAML::NodeType::Map);
      item.SetStyle(YAML::EmitterStyle::Flow);
      item["amplitude"] = plain(h.amplitude);
      item["phase"] = quantity(h.phase_rad, "rad");
      list.push_back(item);
    }
    n["harmonics"] = list;
  }
  if (d.waveform == Waveform::kSamples) {
    YAML::Node list(YAML::NodeType::Sequence);
    list.SetStyle(YAML::EmitterStyle::Flow);
    for (double s : d.samples) list.push_back(plain(s));
    n["samples"] = list;
  }
  if (d.irregularity != 0) n["irregularity"] = plain(d.irregularity);
  return n;
}

/// A path the scene wrote relative to its own folder, made relative to the output's folder.
void rebase(YAML::Node node, const std::filesystem::path& from_dir, const std::filesystem::path& to_dir) {
  if (!node || !node.IsScalar()) return;
  const std::filesystem::path p = node.as<std::string>();
  if (p.is_absolute()) return;
  node = std::filesystem::absolute(from_dir / p).lexically_normal().lexically_relative(std::filesystem::absolute(to_dir)).string();
}

/// Our tree back as yaml-cpp's, for its emitter: scalars as the text they were, flow style kept.
YAML::Node to_yaml(const Node& node) {
  YAML::Node out;
  switch (node.kind) {
    case Node::Kind::kNull:
      return YAML::Node(YAML::NodeType::Null);
    case Node::Kind::kScalar:
      return YAML::Node(node.scalar);
    case Node::Kind::kList:
      out = YAML::Node(YAML::NodeType::Sequence);
      for (const Node& item : node.items) out.push_back(to_yaml(item));
      break;
    case Node::Kind::kMap:
      out = YAML::Node(YAML::NodeType::Map);
      for (const MapEntry& entry : node.entries) out[entry.key] = to_yaml(entry.value);
      break;
  }
  if (node.flow) out.SetStyle(YAML::EmitterStyle::Flow);
  return out;
}

/// The scene's YAML as load read it: the file again, and the -D overrides on it through the
/// one code path that applies them (scene/overrides.h).
YAML::Node scene_as_loaded(const Scene& scene) {
  std::ifstream in(scene.path, std::ios::binary);
  if (!in) throw Error(ExitCode::kNoInput, scene.path + ": cannot read the scene again to write the tuned one");
  std::ostringstream text;
  text << in.rdbuf();
  Node root = parse_yaml(text.str(), scene.path);
  for (const std::string& assignment : scene.overrides) apply_override(root, assignment);
  return to_yaml(root);
}

std::string leading_comments(const std::string& path) {
  std::ifstream in(path);
  std::string line, out;
  while (std::getline(in, line) && line.rfind('#', 0) == 0) out += line + "\n";
  return out;
}

}  // namespace

std::string scene_yaml_with_regions(const Scene& scene, const std::vector<OrganRegions>& changes,
                                    const std::filesystem::path& output, const std::string& note) {
  YAML::Node root = scene_as_loaded(scene);
  const std::filesystem::path from_dir = std::filesystem::path(scene.path).parent_path();
  const std::filesystem::path to_dir = output.parent_path().empty() ? std::filesystem::path(".") : output.parent_path();
  for (YAML::Node organ : root["organs"]) {
    rebase(organ["mesh"]["file"], from_dir, to_dir);
    if (organ["target"] && organ["target"]["frames"]) {
      for (YAML::Node frame : organ["target"]["frames"]) rebase(frame["file"], from_dir, to_dir);
    }
    const std::string name = organ["name"].as<std::string>();
    for (const OrganRegions& change : changes) {
      if (change.organ != name) continue;
      for (YAML::Node region : organ["regions"]) {
        const std::string region_name = region["name"].as<std::string>();
        for (const Region& tuned : change.regions) {
          if (tuned.name != region_name || tuned.pinned) continue;
          if (tuned.drive.waveform != Waveform::kNone || region["drive"]) region["drive"] = drive_node(tuned.drive);
          if (tuned.stiffness_scale != 1 || region["stiffness"]) region["stiffness"] = plain(tuned.stiffness_scale);
        }
      }
    }
  }
  YAML::Emitter out;
  out.SetIndent(2);
  out << root;
  if (!out.good()) throw Error(ExitCode::kInternal, std::string("writing the tuned scene: ") + out.GetLastError());
  return leading_comments(scene.path) + note + out.c_str() + "\n";
}

}  // namespace systole::scene
