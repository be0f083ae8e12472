#include "tide/serve/web_server.hpp"

#include <civetweb.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>
#include <vector>

#include "tide/serve/command.hpp"
#include "tide/serve/static_files.hpp"

namespace tide::serve {
namespace {

using Clock = std::chrono::steady_clock;

constexpr auto state_interval = std::chrono::milliseconds(250);  // how often a page gets the state

// A page's connection: a thread sends it the newest frame whenever there is one it has not had,
// and the state every state_interval.
struct Watcher {
  mg_connection* connection = nullptr;
  std::atomic<bool> open{true};
  std::thread sender;
};

bool send(mg_connection* connection, int opcode, const std::string& data) {
  mg_lock_connection(connection);
  const int sent = mg_websocket_write(connection, opcode, data.data(), data.size());
  mg_unlock_connection(connection);
  return sent > 0;
}

void send_frames(Watcher& watcher, const LiveSimulation& simulation) {
  std::uint64_t last = 0;
  Clock::time_point last_state{};
  while (watcher.open) {
    const Clock::time_point now = Clock::now();
    const PublishedFrame frame =
        simulation.wait_for_frame(last, std::min(now + state_interval, last_state + state_interval));
    if (!watcher.open) return;
    if (frame.number > last && frame.message) {
      if (!send(watcher.connection, MG_WEBSOCKET_OPCODE_BINARY, *frame.message)) return;
      last = frame.number;
    }
    if (Clock::now() - last_state >= state_interval) {
      if (!send(watcher.connection, MG_WEBSOCKET_OPCODE_TEXT, simulation.state_json())) return;
      last_state = Clock::now();
    }
  }
}

std::string reply(const ParsedCommand& parsed, bool ok, const std::string& message) {
  return nlohmann::json{{"type", "reply"}, {"command", parsed.name}, {"ok", ok}, {"message", message}}.dump();
}

// A WebSocket request from a page is let in only from the server's own pages: a browser sends
// its page's origin, which must be this server's (other sites cannot drive the simulation).
bool from_own_page(const mg_request_info& request) {
  const char* origin = nullptr;
  const char* host = nullptr;
  for (int k = 0; k < request.num_headers; ++k) {
    const std::string name = request.http_headers[k].name;
    if (mg_strcasecmp(name.c_str(), "Origin") == 0) origin = request.http_headers[k].value;
    if (mg_strcasecmp(name.c_str(), "Host") == 0) host = request.http_headers[k].value;
  }
  if (origin == nullptr) return true;  // not a browser
  return host != nullptr && std::string(origin) == std::string("http://") + host;
}

}  // namespace

WebServer::WebServer(LiveSimulation& simulation, ServerOptions options)
    : simulation_(simulation), options_(std::move(options)) {
  mg_init_library(0);
  const std::string host = options_.host.find(':') != std::string::npos ? "[" + options_.host + "]" : options_.host;
  const std::string ports = host + ":" + std::to_string(options_.port);
  // Each watching page holds a worker thread; the rest serve files and the state.
  const std::string threads = std::to_string(options_.most_watchers + 8);
  const char* settings[] = {"listening_ports",
                            ports.c_str(),
                            "num_threads",
                            threads.c_str(),
                            "request_timeout_ms",
                            "10000",
                            "websocket_timeout_ms",
                            "10000",
                            "enable_websocket_ping_pong",
                            "yes",
                            nullptr};
  mg_callbacks callbacks{};
  context_ = mg_start(&callbacks, this, settings);
  if (context_ == nullptr) {
    mg_exit_library();
    throw std::runtime_error("cannot listen on " + ports + " (in use, or not an address of this machine)");
  }
  mg_server_port listening[4]{};
  if (mg_get_server_ports(context_, 4, listening) > 0) port_ = listening[0].port;
  mg_set_request_handler(context_, "/state", serve_state, this);
  mg_set_websocket_handler(context_, "/live", on_connect, on_ready, on_message, on_close, this);
  mg_set_request_handler(context_, "**", serve_file, this);
}

WebServer::~WebServer() {
  mg_stop(context_);
  mg_exit_library();
}

std::string WebServer::url() const {
  const std::string host = options_.host.find(':') != std::string::npos ? "[" + options_.host + "]" : options_.host;
  return "http://" + host + ":" + std::to_string(port_) + "/";
}

int WebServer::serve_file(mg_connection* connection, void* server) {
  const auto& self = *static_cast<WebServer*>(server);
  const mg_request_info& request = *mg_get_request_info(connection);
  const std::string method = request.request_method;
  if (method != "GET" && method != "HEAD") {
    mg_send_http_error(connection, 405, "%s", "Only GET and HEAD");
    return 405;
  }
  // The decoded path as sent, before civetweb removes "..": find_static_file refuses those.
  const char* path = request.local_uri_raw != nullptr ? request.local_uri_raw : "";
  const std::optional<StaticFile> file = find_static_file(self.options_.web_root, path);
  std::ifstream in;
  if (file) in.open(file->path, std::ios::binary);
  if (!file || !in) {
    mg_send_http_error(connection, 404, "%s", "Not found");
    return 404;
  }
  const std::string body{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  mg_send_http_ok(connection, file->content_type.c_str(), static_cast<long long>(body.size()));
  if (method == "GET") mg_write(connection, body.data(), body.size());
  return 200;
}

int WebServer::serve_state(mg_connection* connection, void* server) {
  const std::string state = static_cast<WebServer*>(server)->simulation_.state_json();
  mg_send_http_ok(connection, "application/json", static_cast<long long>(state.size()));
  mg_write(connection, state.data(), state.size());
  return 200;
}

int WebServer::on_connect(const mg_connection* connection, void* server) {
  auto& self = *static_cast<WebServer*>(server);
  if (!from_own_page(*mg_get_request_info(connection))) return 1;
  if (self.watchers_.fetch_add(1) >= self.options_.most_watchers) {
    self.watchers_.fetch_sub(1);
    return 1;
  }
  return 0;
}

void WebServer::on_ready(mg_connection* connection, void* server) {
  auto& self = *static_cast<WebServer*>(server);
  auto watcher = std::make_unique<Watcher>();
  watcher->connection = connection;
  Watcher& held = *watcher;
  mg_set_user_connection_data(connection, watcher.release());  // on_close takes it back
  held.sender = std::thread([&held, &self] { send_frames(held, self.simulation_); });
}

int WebServer::on_message(mg_connection* connection, int flags, char* data, std::size_t length, void* server) {
  auto& self = *static_cast<WebServer*>(server);
  const int opcode = flags & 0x0f;
  const bool final_fragment = (flags & 0x80) != 0;
  if (opcode == MG_WEBSOCKET_OPCODE_PING || opcode == MG_WEBSOCKET_OPCODE_PONG) return 1;
  // A binary, fragmented, oversized or closing message ends this page's connection only.
  if (opcode != MG_WEBSOCKET_OPCODE_TEXT || !final_fragment || length > largest_command_bytes) return 0;
  const ParsedCommand parsed = parse_command(std::string_view(data, length));
  if (parsed.garbage) {
    send(connection, MG_WEBSOCKET_OPCODE_TEXT, reply(parsed, false, parsed.message + ": closing the connection"));
    return 0;
  }
  if (!parsed.command) return send(connection, MG_WEBSOCKET_OPCODE_TEXT, reply(parsed, false, parsed.message)) ? 1 : 0;
  if (!self.simulation_.submit(*parsed.command))
    return send(connection, MG_WEBSOCKET_OPCODE_TEXT, reply(parsed, false, "busy: too many commands waiting")) ? 1 : 0;
  return send(connection, MG_WEBSOCKET_OPCODE_TEXT, reply(parsed, true, parsed.message)) ? 1 : 0;
}

void WebServer::on_close(const mg_connection* connection, void* server) {
  auto& self = *static_cast<WebServer*>(server);
  const std::unique_ptr<Watcher> watcher(static_cast<Watcher*>(mg_get_user_connection_data(connection)));
  if (watcher) {
    watcher->open = false;
    watcher->sender.join();
  }
  self.watchers_.fetch_sub(1);
}

}  // namespace tide::serve
