// The root table (the scene map and its cross-organ checks) and the public entry points of
// scene/schema.h that read a tree.

#include <algorithm>
#include <limits>

#include "scene/schema/parts.h"

namespace systole::scene::schema {
namespace {

/// Contact pairs name two organs of the scene, once each, not two colliders.
void check_contact(const Node& node, const Scene& s) {
  if (!s.contact.enabled) return;
  const auto organ = [&](const std::string& name) {
    return std::find_if(s.organs.begin(), s.organs.end(), [&](const Organ& o) { return o.name == name; });
  };
  for (std::size_t i = 0; i < s.contact.pairs.size(); ++i) {
    const ContactPair& p = s.contact.pairs[i];
    const std::string path = "contact.pairs[" + std::to_string(i) + "].organs";
    for (int k = 0; k < 2; ++k)
      if (organ(p.organs[k]) == s.organs.end())
        fail(node.find("contact")->find("pairs")->items[i].find("organs")->items[k].origin,
             path + "[" + std::to_string(k) + "]", "no organ is named '" + p.organs[k] + "'");
    if (organ(p.organs[0])->collider && organ(p.organs[1])->collider)
      fail(p.origin, path, "both organs are colliders: neither can move, so they never touch");
    for (std::size_t j = 0; j < i; ++j) {
      const ContactPair& q = s.contact.pairs[j];
      if ((q.organs[0] == p.organs[0] && q.organs[1] == p.organs[1]) || (q.organs[0] == p.organs[1] && q.organs[1] == p.organs[0]))
        fail(p.origin, path, "the pair is listed twice (also contact.pairs[" + std::to_string(j) + "])");
    }
  }
}

ValueSpec<Scene> scene_spec() {
  auto light = map<Light>({
      field("direction", direction(), &Light::direction, "Direction the light travels."),
      field("color", color(), &Light::color, "Light colour (sRGB)."),
      field("intensity", number(closed(0, 100)), &Light::intensity, "Brightness multiplier."),
  });
  return map<Scene>(
      {
          field("seed", whole<std::uint64_t>(0, std::numeric_limits<std::int64_t>::max()), &Scene::seed,
                "Seeds every random choice (irregular rhythms, tuning)."),
          field("gravity", vec3(Dimension::kAcceleration), &Scene::gravity, "Gravity acceleration."),
          field("organs", list(organ_spec(), 1, 64, "list of organs"), &Scene::organs, "The soft bodies in the scene.")
              .required(),
          field("interactions", list(interaction_spec(), 0, 256, "list of interactions"), &Scene::interactions,
                "Scripted pokes and grabs on the timeline."),
          field("floor", floor_spec(), &Scene::floor, "A plane the organs cannot pass through.").shown_default("none"),
          field("contact", contact_spec(), &Scene::contact,
                "Organs that touch: their surfaces kept apart, every organ stepped in one coupled step "
                "(docs/contact.md).")
              .shown_default("none (organs pass through each other)"),
          field("solver", solver_spec(), &Scene::solver, "Time integration."),
          field("camera", camera_spec(), &Scene::camera, "The view."),
          field("lights", list(light, 1, 8, "list of lights"), &Scene::lights, "Directional lights.")
              .shown_default("a warm key and a cool fill"),
          field("views", list(view_spec(), 0, 16, "list of views"), &Scene::views,
                "Split screen: panels side by side (up to 3) or in a grid, each with its own camera, organs and cut.")
              .shown_default("one view of every organ"),
          field("output", output_spec(), &Scene::output, "The video file."),
          field("cards", list(card_spec(), 0, 16, "list of cards"), &Scene::cards,
                "Title cards shown in order before the clip: text on the background colour, fading in and out."),
          field("captions", list(caption_spec(), 0, 256, "list of captions"), &Scene::captions,
                "Text at the bottom of the clip over a time range, fading in and out."),
          field("chapters", list(chapter_spec(), 0, 256, "list of chapters"), &Scene::chapters,
                "Chapter marks of the video (each title card is one too), in increasing time."),
          field("audio", audio_spec(), &Scene::audio,
                "A soundtrack that follows the simulation: heart sounds, breath sounds, a click (docs/sound.md).")
              .shown_default("none"),
          field("overlay", overlay_spec(), &Scene::overlay,
                "Teaching overlays drawn on each frame: title, region labels, legend, trace insets "
                "(docs/teaching-visuals.md)."),
      },
      [](const Node& node, Scene& s, const std::string&, const Context&) {
        if (!node.find("lights")) s.lights = default_lights();
        if (s.output.loop) resolve_loop(node, s);
        for (std::size_t i = 0; i < s.interactions.size(); ++i) {
          const auto& name = s.interactions[i].organ;
          if (std::none_of(s.organs.begin(), s.organs.end(), [&](const Organ& o) { return o.name == name; }))
            fail(s.interactions[i].origin, "interactions[" + std::to_string(i) + "]",
                 "no organ is named '" + name + "'");
        }
        for (std::size_t i = 0; i < s.views.size(); ++i)
          for (std::size_t k = 0; k < s.views[i].organs.size(); ++k) {
            const auto& name = s.views[i].organs[k];
            if (std::none_of(s.organs.begin(), s.organs.end(), [&](const Organ& o) { return o.name == name; }))
              fail(node.find("views")->items[i].find("organs")->items[k].origin,
                   "views[" + std::to_string(i) + "].organs[" + std::to_string(k) + "]",
                   "no organ is named '" + name + "'");
          }
        for (std::size_t i = 0; i < s.organs.size(); ++i)
          for (std::size_t j = 0; j < i; ++j)
            if (s.organs[i].name == s.organs[j].name)
              fail(origin_of(node.find("organs")->items[i], "name"), "organs[" + std::to_string(i) + "].name",
                   "duplicate organ name '" + s.organs[i].name + "' (also organs[" + std::to_string(j) + "])");
        check_contact(node, s);
        check_overlay(node, s);
        check_audio(node, s);
        const Node* chapters = node.find("chapters");
        for (std::size_t i = 1; i < s.chapters.size(); ++i)
          if (s.chapters[i].at_s <= s.chapters[i - 1].at_s)
            fail(origin_of(chapters->items[i], "at"), "chapters[" + std::to_string(i) + "].at",
                 format_quantity(s.chapters[i].at_s, Dimension::kTime) + " must be after the chapter before (" +
                     format_quantity(s.chapters[i - 1].at_s, Dimension::kTime) + ")");
      });
}

}  // namespace

const ValueSpec<Scene>& the_scene_spec() {
  static const ValueSpec<Scene> spec = scene_spec();
  return spec;
}

}  // namespace systole::scene::schema

namespace systole::scene {

const KeySpec* KeySpec::find(const std::string& key) const {
  for (const KeySpec& k : keys)
    if (k.name == key) return &k;
  return nullptr;
}

std::vector<std::string> KeySpec::key_names() const {
  std::vector<std::string> names;
  for (const KeySpec& k : keys) names.push_back(k.name);
  return names;
}

const KeySpec& scene_schema() {
  static const KeySpec root{"", "map", "", "", "A scene.", schema::the_scene_spec().keys};
  return root;
}

Scene read_scene(const Node& root, const std::filesystem::path& base_dir) {
  Scene scene;
  schema::the_scene_spec().read(root, scene, "", schema::Context{base_dir});
  return scene;
}

}  // namespace systole::scene
