// Solver method names (scene/world.h): each method's name is the word a scene writes for it,
// so what the tools print reads back as the same method.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "scene/load.h"
#include "scene/scene.h"
#include "scene/world.h"

namespace systole::scene {
namespace {

TEST(MethodName, EveryMethodsNameLoadsAsThatMethod) {
  std::set<std::string> names;
  for (SolverMethod m : {SolverMethod::kXpbd, SolverMethod::kExplicit, SolverMethod::kImplicit, SolverMethod::kProjective}) {
    const std::string name = method_name(m);
    names.insert(name);
    const Scene s = load_from_string(
        "organs:\n  - name: heart\n    mesh: {procedural: heart, detail: 1}\n    body: {mass: 300 g, stiffness: 400 N/m}\n"
        "solver: {method: " + name + "}\n",
        "method.yaml");
    EXPECT_EQ(s.solver.method, m) << name;
  }
  EXPECT_EQ(names.size(), 4u);  // No two methods share a name.
}

}  // namespace
}  // namespace systole::scene
