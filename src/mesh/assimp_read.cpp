#include "mesh/assimp_read.h"

#include <pthread.h>

#include <cstring>
#include <exception>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"
#include "mesh/file_bounds.h"

namespace systole::mesh {
namespace {

constexpr std::size_t kReaderStackBytes = std::size_t{256} << 20;

/// Runs `work` on a thread with a stack of `bytes`, waits for it, and rethrows what it threw.
void run_with_stack(std::size_t bytes, const std::function<void()>& work) {
  struct Job {
    const std::function<void()>* work;
    std::exception_ptr error;
  } job{&work, nullptr};
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  pthread_attr_setstacksize(&attributes, bytes);
  pthread_t thread;
  const int started = pthread_create(
      &thread, &attributes,
      [](void* argument) -> void* {
        auto* j = static_cast<Job*>(argument);
        try {
          (*j->work)();
        } catch (...) {
          j->error = std::current_exception();
        }
        return nullptr;
      },
      &job);
  pthread_attr_destroy(&attributes);
  if (started != 0) {
    work();  // No thread to be had (a process limit): read on this one, with its own stack.
    return;
  }
  pthread_join(thread, nullptr);
  if (job.error) std::rethrow_exception(job.error);
}

/// The graph's node count and depth, walked with an explicit stack. The root stands for the
/// file (assimp makes one up for formats with several roots): it is level 0, not counted.
void check_graph(const aiScene& scene, const std::filesystem::path& file) {
  const ImportLimits& limits = import_limits();
  std::int64_t nodes = 0;
  std::vector<std::pair<const aiNode*, int>> stack;
  if (scene.mRootNode != nullptr) stack.emplace_back(scene.mRootNode, 0);
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    if (depth > 0 && ++nodes > limits.max_nodes) {
      throw Error(ExitCode::kDataError, file.string() + ": the scene graph has over " + grouped(double(limits.max_nodes)) +
                                            " nodes; a mesh file may hold at most that many (docs/robustness.md); pass "
                                            "--allow-large to read it anyway");
    }
    if (depth > limits.max_node_depth) {
      throw Error(ExitCode::kDataError, file.string() + ": the scene graph nests nodes over " +
                                            std::to_string(limits.max_node_depth) +
                                            " levels deep; a mesh file may nest at most that many");
    }
    for (unsigned i = 0; i < node->mNumChildren; ++i) {
      if (node->mChildren[i] != nullptr) stack.emplace_back(node->mChildren[i], depth + 1);
    }
  }
}

}  // namespace

const aiScene* read_with_assimp(Assimp::Importer& importer, const std::filesystem::path& file, unsigned post_processing) {
  const aiScene* scene = nullptr;
  run_with_stack(kReaderStackBytes, [&] {
    scene = importer.ReadFile(file.string(), 0);
    if (scene == nullptr) return;
    check_graph(*scene, file);
    if (post_processing == 0) return;
    try {
      scene = importer.ApplyPostProcessing(post_processing);
    } catch (const std::exception& e) {  // An assimp assertion (mesh/import.cpp) in a step.
      throw Error(ExitCode::kDataError, file.string() + ": cannot read as a mesh (assimp: " + e.what() + ")");
    }
  });
  if (scene == nullptr) {
    throw Error(ExitCode::kDataError, file.string() + ": cannot read as a mesh (assimp: " + importer.GetErrorString() + ")");
  }
  return scene;
}

}  // namespace systole::mesh
