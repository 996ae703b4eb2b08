#pragma once
// The tables of the schema, one function per scene struct, for the files that nest them
// (the scene map nests organs, solver, camera, ...). Each returns a fresh ValueSpec.

#include <string>
#include <vector>

#include "scene/schema/spec.h"

namespace systole::scene::schema {

// organ.cpp
ValueSpec<Drive> drive_spec();
/// A list of {time, position} keys with increasing times.
ValueSpec<std::vector<PathKey>> path_keys(std::string position_doc);
ValueSpec<ClipPlane> clip_spec();
ValueSpec<Organ> organ_spec();

// target.cpp
ValueSpec<Target> target_spec();
/// The target's region names and lock entries must name the organ's regions.
void check_target_names(const Node& node, const Organ& o, const std::string& path);

// body.cpp
ValueSpec<Body> body_spec();
/// The blood in an anatomical heart's ventricles.
ValueSpec<Blood> blood_spec();

// world.cpp
ValueSpec<Solver> solver_spec();
ValueSpec<Interaction> interaction_spec();
ValueSpec<Floor> floor_spec();
ValueSpec<Contact> contact_spec();
ValueSpec<Camera> camera_spec();
/// A warm key light from the upper left and a cool, dimmer fill from the right, so the
/// organ reads as a solid even when a scene names no lights.
std::vector<Light> default_lights();

// output.cpp
ValueSpec<Card> card_spec();
ValueSpec<Caption> caption_spec();
ValueSpec<Output> output_spec();
/// output.loop: duration becomes the shortest whole number of cycles of the slowest drive
/// in which every other drive also completes whole cycles (within 0.1% of a cycle), times
/// round(duration / that); start_frame skips settle_cycles of the slowest drive, rounded up to
/// whole loops, so the clip starts at the same phase as t = 0.
void resolve_loop(const Node& node, Scene& s);

ValueSpec<Chapter> chapter_spec();

// audio.cpp
ValueSpec<Audio> audio_spec();
/// Cross-checks of the audio against the organs; fills in the heart organ and its
/// ventricular regions, and the breathing organ, when the scene leaves them out.
void check_audio(const Node& root, Scene& s);

// overlay.cpp
ValueSpec<View> view_spec();
ValueSpec<Overlay> overlay_spec();
/// Cross-checks of the overlay against the organs: every name it uses exists, and traced
/// regions are driven.
void check_overlay(const Node& root, const Scene& s);

}  // namespace systole::scene::schema
