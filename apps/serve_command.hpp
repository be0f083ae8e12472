#pragma once

#include <filesystem>
#include <string>

namespace tide::app {

struct ServeOptions {
  std::filesystem::path scene_file;
  std::filesystem::path web_root;  // the page's files (web/)
  std::string host = "127.0.0.1";
  int port = 8080;  // 0: any free port
  double pace = 1;  // simulated seconds per wall second at most; 0: as fast as it runs
};

/// `tide serve`: runs a 2D scene live and serves the page that shows it and drives it
/// (docs/serve.md), until SIGINT or SIGTERM.
int serve_scene(const ServeOptions& options);

}  // namespace tide::app
