// ctest-labels: no-sanitizers
// The hostile-input corpus, mesh files (tests/hostile/README.md): each file is generated
// here (tests/support/hostile_meshes.h), read through `systole validate`, and must end with
// its exit code and a message naming the limit or the cause, within 2 s of CPU time and
// 300 MB of peak memory (wait4's rusage; no sanitizers, whose shadow memory would count).
// Before the bounds, the deep chain overflowed the stack (exit 139), the 100,000 instances
// took 118 s, the 2.1 M-vertex OBJ 21.5 s and 2.4 GB, the cut OBJ was read silently.

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "support/hostile_meshes.h"
#include "support/measure.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

struct Case {
  std::string name;                               ///< The file, in the corpus folder.
  std::function<void(const fs::path&)> generate;  ///< Writes it.
  int exit_code;
  std::string message;                   ///< A part of what the run says.
  std::vector<std::string> extra = {};  ///< More arguments (--allow-large, -D ...).
};

void write_glb(const fs::path& file, const std::string& nodes, const std::string& roots = "[0]") {
  write_binary(file, glb(nodes, roots));
}

/// An OBJ of `vertices` lines and one face, streamed (it is 40 MB).
void write_many_vertices(const fs::path& file, int vertices) {
  std::ofstream out(file, std::ios::binary);
  char line[64];
  for (int i = 0; i < vertices; ++i) {
    const int n = std::snprintf(line, sizeof line, "v %d 0.5 0.25\n", i);
    out.write(line, n);
  }
  out << "f 1 2 3\n";
}

std::vector<Case> corpus() {
  std::vector<Case> cases;
  cases.push_back({"chain-20000.glb", [](const fs::path& f) { write_glb(f, chain_nodes(20000)); }, 65,
                   "the glTF scene graph has over 10,000 nodes"});
  cases.push_back({"chain-9000.glb", [](const fs::path& f) { write_glb(f, chain_nodes(9000)); }, 65,
                   "nests nodes over 256 levels deep"});
  // Lifted, the same chain is read (on the reader's own stack), not a crash.
  cases.push_back({"chain-20000-allowed.glb", [](const fs::path& f) { write_glb(f, chain_nodes(20000)); }, 0, "ok",
                   {"--allow-large"}});
  cases.push_back({"instances-100000.glb",
                   [](const fs::path& f) {
                     std::string roots;
                     const std::string nodes = wide_nodes(100000, &roots);
                     write_glb(f, nodes, roots);
                   },
                   65, "the glTF scene graph has over 10,000 nodes"});
  cases.push_back({"cycle.glb", [](const fs::path& f) { write_glb(f, R"([{"children":[1],"mesh":0},{"children":[0]}])"); },
                   65, "node 0 is reached twice from the roots"});
  cases.push_back({"nested-json.glb",
                   [](const fs::path& f) {
                     write_glb(f, R"([{"mesh":0,"extras":)" + std::string(1 << 20, '[') + std::string(1 << 20, ']') + "}]");
                   },
                   65, "JSON nested over 128 levels deep"});
  cases.push_back({"parts-20000.obj",
                   [](const fs::path& f) {
                     std::ofstream out(f);
                     for (int i = 0; i < 20000; ++i) {
                       const double x = 1e-3 * (i % 150), y = 1e-3 * (i / 150);
                       out << "o p" << i << "\nv " << x << " " << y << " 0\nv " << x + 8e-4 << " " << y << " 0\nv " << x
                           << " " << y + 8e-4 << " 5e-4\nf " << 3 * i + 1 << " " << 3 * i + 2 << " " << 3 * i + 3 << "\n";
                     }
                   },
                   65, "the scene graph has over 10,000 nodes"});
  cases.push_back({"vertices-2100000.obj", [](const fs::path& f) { write_many_vertices(f, 2'100'000); }, 65,
                   "the OBJ file holds 2,100,000 vertices; a mesh file may hold at most 2,000,000"});
  cases.push_back({"cut-2000000-faces.obj",
                   [](const fs::path& f) { write_binary(f, grid_obj(800, "# 2000000 faces\n", "f 12/")); }, 65,
                   "the file is cut short: its last line 'f 12/' stops in the middle of a record"});
  cases.push_back({"stl-claims-100000000.stl",
                   [](const fs::path& f) { write_binary(f, std::string(80, ' ') + le32(100'000'000) + std::string(500, '\0')); },
                   65, "the STL header declares 100,000,000 faces"});
  cases.push_back({"units-by-define.obj", [](const fs::path& f) { write_binary(f, grid_obj(40)); }, 65,
                   "-D organs.0.mesh.units=mm: organ 'organ': the mesh is", {"-D", "organs.0.mesh.units=mm"}});
  return cases;
}

TEST(HostileMeshes, EachFileEndsWithItsCodeAndCauseWithinTwoSecondsAndThreeHundredMegabytes) {
  const fs::path dir = scratch("hostile_meshes");
  for (const Case& c : corpus()) {
    SCOPED_TRACE(c.name);
    const fs::path file = dir / c.name;
    c.generate(file);
    const fs::path scene = dir / (c.name + ".yaml");
    std::ofstream(scene) << "organs:\n  - name: organ\n    mesh: {file: " << file.filename().string() << ", units: m}\n";
    std::vector<std::string> args = {"validate", scene.string()};
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    const Measured m = measure(args);
    EXPECT_EQ(m.exit_code, c.exit_code) << m.errors.substr(0, 1000);
    if (c.exit_code != 0) EXPECT_NE(m.errors.find(c.message), std::string::npos) << m.errors.substr(0, 1000);
    EXPECT_LT(m.cpu_s, 2.0) << "seconds of CPU";
    EXPECT_LT(m.peak_mb, 300.0) << "MB at peak";
    std::printf("[ corpus   ] %-28s exit %3d, %.2f s CPU, %4.0f MB peak (%.1f MB file)\n", c.name.c_str(), m.exit_code,
                m.cpu_s, m.peak_mb, static_cast<double>(fs::file_size(file)) / 1e6);
    fs::remove(file);  // The corpus is 100 MB at its largest; keep one file at a time.
  }
}

}  // namespace
}  // namespace systole::test
