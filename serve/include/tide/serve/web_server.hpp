#pragma once

// The HTTP and WebSocket server of `tide serve` (civetweb): the page's files from the static
// folder, the live simulation's frames and state on the WebSocket /live, its state as JSON at
// GET /state (docs/serve.md).

#include <atomic>
#include <filesystem>
#include <string>

#include "tide/serve/live_simulation.hpp"

struct mg_context;
struct mg_connection;

namespace tide::serve {

struct ServerOptions {
  std::string host = "127.0.0.1";
  int port = 8080;  // 0: a free port, which port() tells
  std::filesystem::path web_root;
  int most_watchers = 16;  // pages watching at once; one more is refused
};

class WebServer {
 public:
  /// Listens on options.host:options.port; std::runtime_error when it cannot.
  WebServer(LiveSimulation& simulation, ServerOptions options);
  ~WebServer();
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  int port() const { return port_; }
  /// "http://HOST:PORT/".
  std::string url() const;

 private:
  static int serve_file(mg_connection* connection, void* server);
  static int serve_state(mg_connection* connection, void* server);
  static int on_connect(const mg_connection* connection, void* server);
  static void on_ready(mg_connection* connection, void* server);
  static int on_message(mg_connection* connection, int flags, char* data, std::size_t length, void* server);
  static void on_close(const mg_connection* connection, void* server);

  LiveSimulation& simulation_;
  ServerOptions options_;
  std::atomic<int> watchers_{0};
  mg_context* context_ = nullptr;
  int port_ = 0;
};

}  // namespace tide::serve
