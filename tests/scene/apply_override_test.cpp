// -D key.path=value on the YAML tree (scene/overrides.h), before validation: map keys,
// list items by index or by name, values parsed as YAML and labelled for messages, maps
// created on the way where the schema has them, and every wrong path refused.

#include "scene/overrides.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "scene/tree.h"

namespace systole::scene {
namespace {

const char* kScene =
    "seed: 1\n"
    "organs:\n"
    "  - name: heart\n"
    "    body: {mass: 300 g, stiffness: 400 N/m}\n"
    "  - name: liver\n"
    "    body: {mass: 1.5 kg}\n"
    "output: {fps: 30, duration: 10 s}\n";

Node scene() { return parse_yaml(kScene, "scene.yaml"); }

const Node& at(const Node& map, std::string_view key) {
  const Node* n = map.find(key);
  if (!n) throw std::runtime_error("no key " + std::string(key));
  return *n;
}

/// The message of the Error(kDataError) that applying `assignment` throws, or "".
std::string refusal(const std::string& assignment) {
  Node root = scene();
  try {
    apply_override(root, assignment);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError) << assignment;
    return e.what();
  }
  return "";
}

TEST(ApplyOverride, ReplacesAScalarAndLabelsItsOrigin) {
  Node root = scene();
  apply_override(root, "seed=9");
  EXPECT_EQ(at(root, "seed").scalar, "9");
  EXPECT_EQ(at(root, "seed").origin.file, "-D seed=9");
  // Everything else is as written.
  EXPECT_EQ(at(root, "output").find("fps")->scalar, "30");
  EXPECT_EQ(at(root, "output").find("fps")->origin.file, "scene.yaml");
}

TEST(ApplyOverride, FindsListItemsByIndexOrByName) {
  Node root = scene();
  apply_override(root, "organs.liver.body.mass=2 kg");
  apply_override(root, "organs.0.body.stiffness=500 N/m");
  const Node& organs = at(root, "organs");
  EXPECT_EQ(at(at(organs.items[1], "body"), "mass").scalar, "2 kg");
  EXPECT_EQ(at(at(organs.items[0], "body"), "stiffness").scalar, "500 N/m");
  EXPECT_EQ(at(at(organs.items[0], "body"), "mass").scalar, "300 g");  // Its neighbour kept.
}

TEST(ApplyOverride, ParsesTheValueAsYaml) {
  Node root = scene();
  apply_override(root, "output={fps: 60, duration: 2 s}");
  const Node& output = at(root, "output");
  ASSERT_EQ(output.kind, Node::Kind::kMap);
  EXPECT_EQ(at(output, "fps").scalar, "60");
  EXPECT_EQ(at(output, "duration").scalar, "2 s");
  EXPECT_EQ(output.find("width"), nullptr);  // The whole map replaced.
  EXPECT_EQ(at(output, "fps").origin.file, "-D output={fps: 60, duration: 2 s}");  // Inner nodes labelled too.
}

TEST(ApplyOverride, AddsAMissingKeyTheSchemaKnows) {
  Node root = scene();
  apply_override(root, "output.width=640");
  EXPECT_EQ(at(at(root, "output"), "width").scalar, "640");
  apply_override(root, "organs.liver.body.damping=5 ms");
  EXPECT_EQ(at(at(at(root, "organs").items[1], "body"), "damping").scalar, "5 ms");
}

TEST(ApplyOverride, RefusesKeysTheSchemaDoesNotHave) {
  EXPECT_NE(refusal("sede=3"), "");
  EXPECT_NE(refusal("output.colour=red"), "");
  EXPECT_NE(refusal("organs.heart.body.weight=1 kg"), "");
}

TEST(ApplyOverride, RefusesMissingItemsAndNamesTheOnesThereAre) {
  const std::string by_index = refusal("organs.2.body.mass=1 kg");
  EXPECT_NE(by_index.find("2 item(s)"), std::string::npos) << by_index;
  const std::string by_name = refusal("organs.lung.body.mass=1 kg");
  EXPECT_NE(by_name.find("heart, liver"), std::string::npos) << by_name;
}

TEST(ApplyOverride, RefusesMalformedAssignments) {
  EXPECT_NE(refusal("seed"), "");             // No '='.
  EXPECT_NE(refusal("=3"), "");               // No key.
  EXPECT_NE(refusal("organs..body=1"), "");   // An empty segment.
  EXPECT_NE(refusal("seed.value=1"), "");     // A scalar has no keys.
}

TEST(ApplyOverride, ARefusalLeavesTheTreeAsItWas) {
  Node root = scene();
  try {
    apply_override(root, "organs.lung.body.mass=1 kg");
  } catch (const Error&) {
  }
  EXPECT_EQ(at(root, "organs").items.size(), 2u);
  EXPECT_EQ(at(at(at(root, "organs").items[1], "body"), "mass").scalar, "1.5 kg");
}

}  // namespace
}  // namespace systole::scene
