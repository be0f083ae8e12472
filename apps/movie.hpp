#pragma once

#include <cstddef>
#include <filesystem>

namespace tide::app {

/// Runs ffmpeg (H.264, yuv420p, 25 frames per second) on the consecutively numbered frames
/// `directory`/frame_NNNNNN.png from `first_frame` on, writing `movie` atomically. Returns false,
/// having printed why, where ffmpeg is not installed or fails; the frames stay either way.
bool assemble_movie(const std::filesystem::path& directory, std::size_t first_frame,
                    const std::filesystem::path& movie);

}  // namespace tide::app
