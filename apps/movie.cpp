#include "movie.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tide/io/atomic_file.hpp"

extern char** environ;

namespace tide::app {
namespace {

/// Runs `arguments` (the program first, looked up on PATH) and waits: its exit status, or -1 with
/// errno set where it could not be started.
int run_program(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t child = 0;
  const int error = posix_spawnp(&child, argv[0], nullptr, nullptr, argv.data(), environ);
  if (error != 0) {
    errno = error;
    return -1;
  }
  int status = 0;
  if (waitpid(child, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

}  // namespace

bool assemble_movie(const std::filesystem::path& directory, std::size_t first_frame,
                    const std::filesystem::path& movie) {
  try {
    io::replace_atomically(movie, [&](const std::filesystem::path& temporary) {
      // Even width and height, which yuv420p needs: pad by a pixel where one is odd.
      const int status =
          run_program({"ffmpeg", "-y", "-loglevel", "error", "-framerate", "25", "-start_number",
                       std::to_string(first_frame), "-i", (directory / "frame_%06d.png").string(), "-c:v", "libx264",
                       "-pix_fmt", "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-f", "mp4", temporary.string()});
      if (status == -1 && errno == ENOENT)
        throw std::runtime_error("ffmpeg is not installed (Debian: apt-get install ffmpeg), so no MP4");
      if (status != 0)
        throw std::runtime_error("ffmpeg failed (exit status " + std::to_string(status) + "), so no MP4");
    });
  } catch (const std::exception& error) {
    std::cout << "tide render: " << error.what() << "; the PNG frames are in " << directory.string() << '\n';
    return false;
  }
  return true;
}

}  // namespace tide::app
