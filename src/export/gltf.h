#pragma once
// glTF 2.0 (.glb binary, .gltf text with its buffer inlined): each organ a mesh node, its
// regions as primitives with their colours as materials, and one animation whose weight
// curves play the organ's morph targets (export/morph.h) in every standard viewer
// (Blender: shape keys and an action; three.js: morphTargetInfluences).
//
// Written through tinygltf (Debian's libtinygltf-dev, a shared library with its own JSON
// writer); the binary chunk is laid out here, 4-byte aligned, POSITION accessors with the
// min and max the specification requires.
//
// Inputs:  a Recording and one MorphAnimation per organ.
// Outputs: the file's bytes (the HTML page inlines them), or the file, written atomically.
// See also: export/html.h, scripts/check-exports (Khronos' validator, Blender), docs/export.md.

#include <filesystem>
#include <string>
#include <vector>

#include "export/morph.h"
#include "export/recording.h"

namespace systole::exporter {

/// The glTF document: binary (GLB container) or JSON with the buffer as a data URI.
std::string gltf_bytes(const Recording& rec, const std::vector<MorphAnimation>& morphs, bool binary);

/// Writes gltf_bytes to `file` atomically (common/atomic_output.h).
void write_gltf(const std::filesystem::path& file, const Recording& rec, const std::vector<MorphAnimation>& morphs,
                bool binary);

}  // namespace systole::exporter
