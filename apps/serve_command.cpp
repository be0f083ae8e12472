#include "serve_command.hpp"

#include <csignal>
#include <exception>
#include <iostream>
#include <optional>

#include "run_command.hpp"
#include "tide/serve/live_simulation.hpp"
#include "tide/serve/web_server.hpp"

namespace tide::app {

int serve_scene(const ServeOptions& options) {
  const std::optional<scene::Scene> scene = load_scene(options.scene_file);
  if (!scene) return exit_bad_input;
  // SIGINT and SIGTERM are blocked in every thread started from here on, and taken by sigwait.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  try {
    serve::LiveSimulation simulation(*scene, {options.pace, 60});
    serve::WebServer server(simulation, {options.host, options.port, options.web_root, 16});
    simulation.start();
    std::cout << "tide serve: " << scene->source << " is running live\n"
              << "tide serve: open " << server.url() << " in a browser (Ctrl-C stops)" << std::endl;
    int signal = 0;
    sigwait(&stop_signals, &signal);
    std::cout << "tide serve: stopping" << std::endl;
  } catch (const std::exception& error) {
    std::cerr << "tide: " << error.what() << '\n';
    return exit_bad_input;
  }
  return exit_ok;
}

}  // namespace tide::app
