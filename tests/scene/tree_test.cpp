// scene/tree.h: the YAML tree with origins, and the messages that point back into it.

#include "scene/tree.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"

namespace systole::scene {
namespace {

/// The message `f` throws as Error(kDataError), or "" when it throws nothing.
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    return e.what();
  }
  return "";
}

TEST(Tree, KeepsKindsOrderAndOrigins) {
  const Node root = parse_yaml("seed: 7\norgans:\n  - name: heart\n  - name: liver\nfloor:\n", "s.yaml");
  ASSERT_EQ(root.kind, Node::Kind::kMap);
  ASSERT_EQ(root.entries.size(), 3u);
  EXPECT_EQ(root.entries[0].key, "seed");
  EXPECT_EQ(root.entries[1].key, "organs");
  EXPECT_EQ(root.entries[2].key, "floor");

  const Node* seed = root.find("seed");
  ASSERT_NE(seed, nullptr);
  EXPECT_EQ(seed->kind, Node::Kind::kScalar);
  EXPECT_EQ(seed->scalar, "7");
  EXPECT_EQ(seed->origin.file, "s.yaml");
  EXPECT_EQ(seed->origin.line, 1);
  EXPECT_EQ(seed->origin.column, 7);

  const Node* organs = root.find("organs");
  ASSERT_NE(organs, nullptr);
  ASSERT_EQ(organs->kind, Node::Kind::kList);
  ASSERT_EQ(organs->items.size(), 2u);
  EXPECT_EQ(organs->items[1].find("name")->scalar, "liver");
  EXPECT_EQ(organs->items[1].origin.line, 4);
  EXPECT_EQ(root.entries[1].key_origin.line, 2);

  EXPECT_EQ(root.find("floor")->kind, Node::Kind::kNull);
  EXPECT_EQ(root.find("camera"), nullptr);
}

TEST(Tree, FindOnAMutableNodeEditsTheTree) {
  Node root = parse_yaml("a: 1\n", "s.yaml");
  root.find("a")->scalar = "2";
  EXPECT_EQ(root.find("a")->scalar, "2");
}

TEST(Tree, DescribesNodesForMessages) {
  EXPECT_EQ(parse_yaml("[1, 2]", "s").describe(), "a list");
  EXPECT_EQ(parse_yaml("{a: 1}", "s").describe(), "a map");
  EXPECT_EQ(parse_yaml("'72 bpm'", "s").describe(), "\"72 bpm\"");
  EXPECT_EQ(Node{}.describe(), "nothing");
}

TEST(Tree, SyntaxErrorsAndDuplicateKeysNameTheLine) {
  const std::string syntax = refusal([] { parse_yaml("a: [1, 2\nb: 3\n", "bad.yaml"); });
  EXPECT_EQ(syntax.rfind("bad.yaml:", 0), 0u) << syntax;
  EXPECT_NE(syntax.find("invalid YAML"), std::string::npos) << syntax;

  const std::string duplicate = refusal([] { parse_yaml("seed: 1\nseed: 2\n", "dup.yaml"); });
  EXPECT_EQ(duplicate.rfind("dup.yaml:2:1: ", 0), 0u) << duplicate;
  EXPECT_NE(duplicate.find("duplicate key 'seed' (first written at line 1)"), std::string::npos) << duplicate;
}

TEST(Tree, WhereAndFailPutFileLineColumnAndPathFirst) {
  EXPECT_EQ(where(Origin{"s.yaml", 4, 9}), "s.yaml:4:9: ");
  EXPECT_EQ(where(Origin{"-D seed=x", 0, 0}), "-D seed=x: ");
  EXPECT_EQ(refusal([] { fail(Origin{"s.yaml", 4, 9}, "organs[0].body", "too heavy"); }),
            "s.yaml:4:9: organs[0].body: too heavy");
  EXPECT_EQ(refusal([] { fail(Origin{"s.yaml", 4, 9}, "", "too heavy"); }), "s.yaml:4:9: too heavy");
}

TEST(Tree, UnknownKeySuggestsOnlyCloseNames) {
  const std::vector<std::string> allowed = {"mass", "stiffness", "damping"};
  EXPECT_EQ(unknown_key_message("stifness", allowed),
            "unknown key 'stifness' (did you mean 'stiffness'?); allowed keys: mass, stiffness, damping");
  EXPECT_EQ(unknown_key_message("colour", allowed), "unknown key 'colour'; allowed keys: mass, stiffness, damping");
}

// validate lists a file's part names with yaml_scalar so that any of them, pasted after
// `part: `, reads back as that very name: names an author may give, and ones YAML would
// otherwise read as something else (null, a comment, a map, a flow list, a number's text).
TEST(Tree, YamlScalarReadsBackAsTheSameText) {
  for (const std::string name :
       {"heart/left_atrium", "Heart.001", "Armature|Valve", "Heart: left", "left #2", "#1", "- apex", "[a, b]", "{a}",
        "null", "~", "true", "007", " padded ", "it's", "say \"hi\"", "tab\there", "two\nlines", "Herz/Vorhof_ä", "*alias",
        "&anchor", "!tag", "%percent", "@at", "`tick`", "?", ":", "-", "heart-0", "Heart.001", "NULL", "Null", "1e3",
        "0x1F", "..", "a.", "---", "...", "_", "x//y"}) {
    const std::string written = yaml_scalar(name);
    const Node root = parse_yaml("part: " + written + "\n", "t.yaml");
    const Node* part = root.find("part");
    ASSERT_NE(part, nullptr) << written;
    EXPECT_EQ(part->kind, Node::Kind::kScalar) << name << " written as " << written;
    EXPECT_EQ(part->scalar, name) << "written as " << written;
  }
  EXPECT_EQ(yaml_scalar("heart/left_atrium"), "heart/left_atrium") << "plain names stay plain, as they are listed";
  EXPECT_EQ(yaml_scalar("null"), "\"null\"");
}

}  // namespace
}  // namespace systole::scene
