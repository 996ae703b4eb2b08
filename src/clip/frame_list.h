#pragma once
// Frame lists, as render farms write them: which frames of a clip to render.
//
// Inputs:  text such as "0,30,60", "10..20", "0..299:10" or a mix ("0,5..9,100..200:50");
//          the Deadline/Nuke spellings "10-20" and "0-299x10" are accepted too.
// Outputs: frame numbers (0-based), sorted, without duplicates.
// See also: clip::RenderRequest::frames, encode::frame_file_name.

#include <string>
#include <vector>

namespace systole::clip {

/// The accepted forms, for error messages and --help.
inline constexpr const char* kFrameListForms =
    "N (one frame), A..B (A to B inclusive), A..B:S (every S-th frame from A to B), comma-separated; "
    "A-B and A-BxS also work; frames count from 0";

/// Parses a frame list for a clip of `frame_count` frames. Throws Error(kUsage) for bad
/// syntax (listing the accepted forms) and for a frame past the clip's end (naming the
/// clip's frame count).
std::vector<int> parse_frame_list(const std::string& text, int frame_count);

/// True when the frames are consecutive (f, f+1, ..., f+n-1): they make one clip.
bool is_contiguous(const std::vector<int>& sorted_frames);

}  // namespace systole::clip
