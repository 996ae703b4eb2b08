#pragma once
// The validated scene: plain structs, every quantity in SI units (metres, seconds,
// hertz, radians, kilograms, newtons) whatever unit the YAML used. Built once by
// scene::load() and never changed afterwards; every default lives here, so a scene only
// says what differs (docs/scenes.md is the reference of every key).

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

// The parts, one header per topic; include only the one you need.
#include "scene/audio.h"
#include "scene/drive.h"
#include "scene/organ.h"
#include "scene/origin.h"
#include "scene/output.h"
#include "scene/teaching.h"
#include "scene/world.h"

namespace systole::scene {

struct Scene {
  std::string path;         ///< The YAML file it came from.
  /// The -D assignments applied to the file, in order: the scene is the file with these, so
  /// a scene written back (systole tune's) applies them too.
  std::vector<std::string> overrides;
  std::string name;         ///< File stem: names default outputs.
  std::uint64_t seed = 1;   ///< Seeds every random choice (irregular rhythms, tuning).
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< unit: m/s^2
  std::vector<Organ> organs;
  std::vector<Interaction> interactions;
  Floor floor;
  Contact contact;          ///< enabled: organs touch, stepped together (docs/contact.md).
  Solver solver;
  Camera camera;
  std::vector<Light> lights;
  std::vector<View> views;  ///< Split screen; empty: one view of every organ with `camera`.
  Output output;
  std::vector<Card> cards;         ///< Shown in order before the clip.
  std::vector<Caption> captions;
  std::vector<Chapter> chapters;   ///< Chapter marks besides the cards'.
  Overlay overlay;
  Audio audio;                     ///< The soundtrack; off unless the scene has `audio:`.
};

/// Whether anything in the scene can move: a region's drive or volume drive (amplitude
/// above 0), a pinned region's motion, a poke or a grab, or gravity on a region that is not
/// pinned. A scene with none of these shows a still organ (world::FrameSource warns).
bool anything_can_move(const Scene& scene);

}  // namespace systole::scene
