#include "mesh/animation.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <assimp/Importer.hpp>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "common/error.h"
#include "mesh/assimp_read.h"
#include "mesh/import.h"

namespace systole::mesh {
namespace {

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  for (unsigned r = 0; r < 4; ++r) {
    for (unsigned c = 0; c < 4; ++c) out(r, c) = m[r][c];
  }
  return out;
}

Eigen::Vector3d apply(const Eigen::Matrix4d& m, const Eigen::Vector3d& p) {
  return m.topLeftCorner<3, 3>() * p + m.topRightCorner<3, 1>();
}

/// The key pair around `t` (ticks) and the fraction between them; clamped at both ends.
template <typename Key>
std::tuple<const Key*, const Key*, double> bracket(const Key* keys, unsigned count, double t) {
  if (count == 1 || t <= keys[0].mTime) return {&keys[0], &keys[0], 0.0};
  if (t >= keys[count - 1].mTime) return {&keys[count - 1], &keys[count - 1], 0.0};
  unsigned i = 0;
  while (i + 2 < count && keys[i + 1].mTime <= t) ++i;
  const double span = keys[i + 1].mTime - keys[i].mTime;
  return {&keys[i], &keys[i + 1], span > 0 ? (t - keys[i].mTime) / span : 0.0};
}

Eigen::Vector3d lerp(const aiVectorKey* keys, unsigned count, double t, const Eigen::Vector3d& fallback) {
  if (count == 0) return fallback;
  const auto [a, b, f] = bracket(keys, count, t);
  const Eigen::Vector3d va(a->mValue.x, a->mValue.y, a->mValue.z), vb(b->mValue.x, b->mValue.y, b->mValue.z);
  return (1 - f) * va + f * vb;
}

/// A node's local transform at t: its channel's keys where it has one, else as written.
Eigen::Matrix4d local_transform(const aiNode* node, const aiNodeAnim* channel, double t) {
  if (channel == nullptr) return to_eigen(node->mTransformation);
  aiVector3D scaling, position;
  aiQuaternion rotation;
  node->mTransformation.Decompose(scaling, rotation, position);
  const Eigen::Vector3d p = lerp(channel->mPositionKeys, channel->mNumPositionKeys, t, {position.x, position.y, position.z});
  const Eigen::Vector3d s = lerp(channel->mScalingKeys, channel->mNumScalingKeys, t, {scaling.x, scaling.y, scaling.z});
  Eigen::Quaterniond q(rotation.w, rotation.x, rotation.y, rotation.z);
  if (channel->mNumRotationKeys > 0) {
    const auto [a, b, f] = bracket(channel->mRotationKeys, channel->mNumRotationKeys, t);
    const Eigen::Quaterniond qa(a->mValue.w, a->mValue.x, a->mValue.y, a->mValue.z);
    const Eigen::Quaterniond qb(b->mValue.w, b->mValue.x, b->mValue.y, b->mValue.z);
    q = qa.slerp(f, qb);
  }
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = q.normalized().toRotationMatrix() * s.asDiagonal();
  m.topRightCorner<3, 1>() = p;
  return m;
}

/// Every node's global transform at t (`animation` null: the rest pose as written).
void global_transforms(const aiNode* node, const Eigen::Matrix4d& parent, const aiAnimation* animation, double t,
                       std::map<const aiNode*, Eigen::Matrix4d>& out) {
  const aiNodeAnim* channel = nullptr;
  for (unsigned c = 0; animation != nullptr && c < animation->mNumChannels; ++c) {
    if (animation->mChannels[c]->mNodeName == node->mName) channel = animation->mChannels[c];
  }
  const Eigen::Matrix4d global = parent * local_transform(node, channel, t);
  out[node] = global;
  for (unsigned i = 0; i < node->mNumChildren; ++i) global_transforms(node->mChildren[i], global, animation, t, out);
}

/// The node that holds mesh `m` (the first, depth first), or null.
const aiNode* node_of_mesh(const aiNode* node, unsigned m) {
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    if (node->mMeshes[i] == m) return node;
  }
  for (unsigned i = 0; i < node->mNumChildren; ++i) {
    if (const aiNode* found = node_of_mesh(node->mChildren[i], m)) return found;
  }
  return nullptr;
}

/// The morph weights of mesh `m` at t, one per anim mesh (zero without a channel).
std::vector<double> morph_weights(const aiScene* scene, const aiAnimation* animation, unsigned m, const aiNode* node, double t) {
  const aiMesh* mesh = scene->mMeshes[m];
  std::vector<double> weights(mesh->mNumAnimMeshes, 0.0);
  for (unsigned c = 0; c < animation->mNumMorphMeshChannels; ++c) {
    const aiMeshMorphAnim* channel = animation->mMorphMeshChannels[c];
    const bool ours = channel->mName == mesh->mName || (node != nullptr && channel->mName == node->mName);
    if (!ours || channel->mNumKeys == 0) continue;
    const auto [a, b, f] = bracket(channel->mKeys, channel->mNumKeys, t);
    for (const auto& [key, share] : {std::pair{a, 1 - f}, std::pair{b, f}}) {
      for (unsigned k = 0; k < key->mNumValuesAndWeights; ++k) {
        if (key->mValues[k] < weights.size()) weights[key->mValues[k]] += share * key->mWeights[k];
      }
    }
  }
  return weights;
}

/// Every vertex of every mesh, in file order, posed at t (`animation` null: at rest).
std::vector<Eigen::Vector3d> pose(const aiScene* scene, const aiAnimation* animation, double t) {
  std::map<const aiNode*, Eigen::Matrix4d> globals;
  global_transforms(scene->mRootNode, Eigen::Matrix4d::Identity(), animation, t, globals);
  std::vector<Eigen::Vector3d> out;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const aiNode* node = node_of_mesh(scene->mRootNode, m);
    const Eigen::Matrix4d placement = node != nullptr ? globals.at(node) : Eigen::Matrix4d::Identity();
    // Morph targets, in the mesh's own space.
    std::vector<Eigen::Vector3d> local(mesh->mNumVertices);
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) local[v] = {mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z};
    if (animation != nullptr && mesh->mNumAnimMeshes > 0) {
      const std::vector<double> weights = morph_weights(scene, animation, m, node, t);
      for (unsigned k = 0; k < mesh->mNumAnimMeshes; ++k) {
        const aiAnimMesh* target = mesh->mAnimMeshes[k];
        if (weights[k] == 0 || target->mVertices == nullptr || target->mNumVertices != mesh->mNumVertices) continue;
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
          const aiVector3D& p = target->mVertices[v];
          local[v] += weights[k] * (Eigen::Vector3d(p.x, p.y, p.z) - Eigen::Vector3d(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z));
        }
      }
    }
    // Skinning (posed only: at rest the mesh sits where its node puts it, as import_mesh reads it).
    if (animation != nullptr && mesh->HasBones()) {
      std::vector<Eigen::Vector3d> skinned(mesh->mNumVertices, Eigen::Vector3d::Zero());
      std::vector<double> total(mesh->mNumVertices, 0.0);
      for (unsigned b = 0; b < mesh->mNumBones; ++b) {
        const aiBone* bone = mesh->mBones[b];
        const aiNode* bone_node = scene->mRootNode->FindNode(bone->mName);
        if (bone_node == nullptr) continue;
        const Eigen::Matrix4d skin = globals.at(bone_node) * to_eigen(bone->mOffsetMatrix);
        for (unsigned w = 0; w < bone->mNumWeights; ++w) {
          const aiVertexWeight& vw = bone->mWeights[w];
          if (vw.mVertexId >= mesh->mNumVertices) continue;
          skinned[vw.mVertexId] += vw.mWeight * apply(skin, local[vw.mVertexId]);
          total[vw.mVertexId] += vw.mWeight;
        }
      }
      for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        out.push_back(total[v] > 0 ? Eigen::Vector3d(skinned[v] / total[v]) : apply(placement, local[v]));
      }
    } else {
      for (unsigned v = 0; v < mesh->mNumVertices; ++v) out.push_back(apply(placement, local[v]));
    }
  }
  return out;
}

/// The file's scene read for its animation, checked: no post-processing that moves or merges
/// vertices (the file's own vertices are what the animation moves).
const aiScene* read_animated(Assimp::Importer& importer, const std::filesystem::path& file) {
  check_mesh_file(file);
  const aiScene* scene = read_with_assimp(importer, file, aiProcess_ValidateDataStructure);
  if (scene->mNumAnimations == 0) throw Error(ExitCode::kDataError, file.string() + ": the file holds no animation");
  if (!(scene->mAnimations[0]->mDuration > 0)) throw Error(ExitCode::kDataError, file.string() + ": the animation has no duration");
  return scene;
}

}  // namespace

AnimatedSurface read_animated_file(const std::filesystem::path& file, int samples, int cycles, int period) {
  Assimp::Importer importer;
  const aiScene* scene = read_animated(importer, file);
  const aiAnimation* animation = scene->mAnimations[0];
  const double ticks_per_s = animation->mTicksPerSecond > 0 ? animation->mTicksPerSecond : 1.0;
  AnimatedSurface out;
  out.file = file.string();
  out.rest = pose(scene, nullptr, 0);
  out.duration = animation->mDuration / ticks_per_s;
  // Triangles and parts, mesh by mesh in the order pose() lists their vertices.
  unsigned base = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const aiNode* node = node_of_mesh(scene->mRootNode, m);
    std::string name = mesh->mName.length > 0 ? mesh->mName.C_Str() : (node != nullptr ? node->mName.C_Str() : "");
    int part = -1;
    if (!name.empty()) {
      const auto it = std::find(out.parts.begin(), out.parts.end(), name);
      part = static_cast<int>(it - out.parts.begin());
      if (it == out.parts.end()) out.parts.push_back(name);
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      for (unsigned k = 1; k + 1 < face.mNumIndices; ++k) {  // Polygons as fans.
        out.triangles.emplace_back(base + face.mIndices[0], base + face.mIndices[k], base + face.mIndices[k + 1]);
      }
    }
    out.vertex_part.insert(out.vertex_part.end(), mesh->mNumVertices, part);
    base += mesh->mNumVertices;
  }
  if (out.parts.empty()) out.vertex_part.clear();
  const double span = out.duration / std::max(1, cycles), start = span * std::clamp(period, 0, std::max(1, cycles) - 1);
  if (samples == 0) samples = kDefaultSamples;
  for (int i = 0; i < samples; ++i) {
    const double t = start + span * double(i) / double(samples);
    out.times.push_back(t);
    out.poses.push_back(pose(scene, animation, t * ticks_per_s));
  }
  return out;
}

}  // namespace systole::mesh
