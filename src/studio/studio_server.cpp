// The Studio's HTTP and WebSocket server (studio_server.hpp).
//
// Design. One io_context on one thread runs every connection. An HttpConnection reads a
// request (header and body bounded), checks Host and Origin (RequestGuard) before it looks
// at anything else, then either answers it (static asset or /api file call) or, for an
// upgrade to /live, hands the socket and the request to a LiveConnection. A
// LiveConnection owns one LiveSession: it answers each message, and its frame timer
// queues a state frame whenever fewer than four frames wait to be written, so a slow
// browser sees fewer frames rather than a growing queue. The timer wakes at 60 Hz; after a
// pointer message it polls the device every millisecond until a report shows that
// message's force change and sends that frame at once (at most kLiveFrameHz): a pointer
// move then shows its force a tick and a report later, not a frame period later, and the
// browser gets no more frames than it needs (each one costs its processes CPU). A frame
// with nothing new for the page (the handle, the force, the buttons and the effects' states
// as they were) is not sent, but for a keep-alive at kKeepAliveFrameHz that carries the
// device's clock on: at rest the browser parses and redraws nothing. When the socket
// closes for any reason, the connection and its session are destroyed, which stops the
// browser's effects.
#include "studio_server.hpp"

#include <utility>  // std::exchange, which Boost 1.74's asio uses without including

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <deque>
#include <string_view>
#include <thread>

#include <nlohmann/json.hpp>

#include "feel/format/sensation_file.hpp"
#include "field_schema.hpp"
#include "live_session.hpp"
#include "protocol_check.hpp"
#include "request_guard.hpp"
#include "studio_assets.hpp"
#include "studio_device.hpp"
#include "workspace.hpp"

namespace feel::studio {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using json = nlohmann::json;

using Request = http::request<http::string_body>;

// Boost 1.74's Beast has its own string_view.
std::string_view sv(beast::string_view s) { return {s.data(), s.size()}; }
beast::string_view bv(std::string_view s) { return {s.data(), s.size()}; }
using Response = http::response<http::string_body>;

std::string_view content_type(std::string_view path) {
    if (path.ends_with(".html")) return "text/html; charset=utf-8";
    if (path.ends_with(".js")) return "text/javascript; charset=utf-8";
    if (path.ends_with(".css")) return "text/css; charset=utf-8";
    if (path.ends_with(".json")) return "application/json";
    if (path.ends_with(".svg")) return "image/svg+xml";
    if (path.ends_with(".png")) return "image/png";
    return "application/octet-stream";
}

// What every connection shares.
struct Shared {
    Workspace workspace;
    std::shared_ptr<StudioDevice> device;
    const ProtocolSchema& schema;
    RequestGuard guard;
    json hello;  // the first message of every live session, less what changes
    std::atomic<int> sessions{0};
};

Response reply(const Request& req, http::status status, std::string body, std::string_view type) {
    Response res{status, req.version()};
    res.set(http::field::server, "feel-studio");
    res.set(http::field::content_type, bv(type));
    res.set(http::field::cache_control, "no-store");
    res.set("X-Content-Type-Options", "nosniff");
    res.keep_alive(req.keep_alive());
    res.body() = std::move(body);
    res.prepare_payload();
    return res;
}

Response json_reply(const Request& req, http::status status, const json& body) {
    return reply(req, status, body.dump(), "application/json");
}

Response error_reply(const Request& req, http::status status, const std::string& message) {
    return json_reply(req, status, json{{"error", message}});
}

std::string string_field(const json& body, const char* key) {
    const auto it = body.find(key);
    if (it == body.end() || !it->is_string()) {
        throw WorkspaceError(std::string("the request needs \"") + key + "\" as a string");
    }
    return it->get<std::string>();
}

std::vector<std::string> example_names() {
    std::vector<std::string> out;
    for (const Asset& a : data_assets()) {
        if (a.path.starts_with("examples/")) out.emplace_back(a.path.substr(9));
    }
    return out;
}

// The /api calls: files in the workspace, and the read-only examples.
Response api(Shared& shared, const Request& req) {
    if (req.method() != http::verb::post) {
        return error_reply(req, http::status::method_not_allowed, "the /api calls take POST with a JSON body");
    }
    json body;
    try {
        body = json::parse(req.body());
    } catch (const json::exception&) {
        return error_reply(req, http::status::bad_request, "the request body is not JSON");
    }
    if (!body.is_object()) return error_reply(req, http::status::bad_request, "the request body must be a JSON object");
    const std::string_view call = sv(req.target()).substr(5);
    Workspace& ws = shared.workspace;
    try {
        if (call == "list") {
            return json_reply(req, http::status::ok,
                              {{"workspace", ws.list()}, {"examples", example_names()}, {"root", ws.root().string()}});
        }
        if (call == "read") {
            if (body.contains("example")) {
                const std::string name = string_field(body, "example");
                const Asset* a = find_data_asset("examples/" + name);
                if (a == nullptr) return error_reply(req, http::status::not_found, "no example named \"" + name + "\"");
                return json_reply(req, http::status::ok, {{"text", a->text()}, {"read_only", true}});
            }
            return json_reply(req, http::status::ok, {{"text", ws.read(string_field(body, "path"))}});
        }
        if (call == "save") {
            const bool overwrite = body.value("overwrite", false);
            return json_reply(req, http::status::ok,
                              {{"text", ws.save(string_field(body, "path"), string_field(body, "text"), overwrite)}});
        }
        if (call == "rename") {
            ws.rename(string_field(body, "from"), string_field(body, "to"));
            return json_reply(req, http::status::ok, json::object());
        }
        if (call == "copy") {
            const std::string text = ws.read(string_field(body, "from"));
            return json_reply(req, http::status::ok, {{"text", ws.save(string_field(body, "to"), text, false)}});
        }
        if (call == "combine") {
            std::vector<std::string> sources;
            const auto s = body.find("sources");
            if (s == body.end() || !s->is_array() || s->size() > 64) {
                throw WorkspaceError("combine needs \"sources\": an array of up to 64 file paths");
            }
            for (const json& p : *s) {
                if (!p.is_string()) throw WorkspaceError("combine: every source is a file path string");
                sources.push_back(p.get<std::string>());
            }
            return json_reply(req, http::status::ok, {{"text", ws.combine(sources, string_field(body, "to"))}});
        }
    } catch (const WorkspaceFileMissing& e) {
        return error_reply(req, http::status::not_found, e.what());
    } catch (const WorkspaceError& e) {
        return error_reply(req, http::status::forbidden, e.what());
    } catch (const format::FormatError& e) {
        return error_reply(req, http::status::unprocessable_entity, e.what());
    }
    return error_reply(req, http::status::not_found,
                       "no API call \"" + std::string(call) + "\" (allowed: list, read, save, rename, copy, combine)");
}

Response handle_http(Shared& shared, const Request& req) {
    const std::string_view target = sv(req.target());
    if (target.starts_with("/api/")) return api(shared, req);
    if (req.method() != http::verb::get && req.method() != http::verb::head) {
        return error_reply(req, http::status::method_not_allowed, "static files take GET");
    }
    std::string_view path = target.substr(0, target.find('?'));
    if (path == "/") path = "/index.html";
    const Asset* a = find_web_asset(path);
    if (a == nullptr) return error_reply(req, http::status::not_found, "no such page: " + std::string(path.substr(0, 100)));
    Response res = reply(req, http::status::ok, std::string(a->text()), content_type(path));
    res.set("Content-Security-Policy",
            "default-src 'self'; connect-src 'self' ws://127.0.0.1:* ws://localhost:*; "
            "style-src 'self' 'unsafe-inline'; img-src 'self' data:");
    return res;
}

// ---------------------------------------------------------------------------------------

class LiveConnection : public std::enable_shared_from_this<LiveConnection> {
    using Clock = std::chrono::steady_clock;

public:
    LiveConnection(tcp::socket socket, Shared& shared)
        : ws_(std::move(socket)), shared_(shared), timer_(ws_.get_executor()) {}

    void start(Request req) {
        request_ = std::move(req);
        // Small frames both ways: Nagle's algorithm would hold a state frame back until the
        // browser acknowledged the last one (up to a delayed ACK, 40 ms on Linux).
        beast::error_code ignored;
        ws_.next_layer().socket().set_option(tcp::no_delay(true), ignored);
        ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
        ws_.read_message_max(kMaxWebSocketMessageBytes);
        ws_.async_accept(request_, [self = shared_from_this()](beast::error_code ec) {
            if (ec) return;
            self->session_.emplace(self->shared_.device, self->shared_.schema);
            self->session_->set_workspace(&self->shared_.workspace);
            ++self->shared_.sessions;
            json hello = self->shared_.hello;
            hello["grip"] = self->shared_.device->grip();
            hello["gain"] = self->shared_.device->device().input().gain;
            self->send(hello.dump());
            self->read();
            self->wait();
        });
    }

    ~LiveConnection() { end_session(); }

private:
    void read() {
        ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, size_t) {
            if (ec) {
                self->close();
                return;
            }
            if (!self->session_) return;  // closed while the read completed
            const auto read_at = Clock::now();  // the Beast read's completion: the server's first hop
            if (!self->ws_.got_text()) {
                self->send(json{{"type", "error"}, {"message", "malformed message: binary frames are not part of the protocol"}}.dump());
            } else {
                const std::string text = beast::buffers_to_string(self->buffer_.data());
                for (const json& r : self->session_->handle(text, read_at)) self->send(r.dump());
            }
            self->buffer_.consume(self->buffer_.size());
            const auto now = read_at;
            // The timer may be a frame period away (at rest, or between two pointer moves,
            // when it waits for the next 60 Hz frame): a pointer message now awaiting its
            // answer brings it forward, so the polling for the answer starts at once.
            if (!self->interacting(now) || self->session_->pointer_awaited()) self->timer_.expires_after(kLivePoll);
            self->last_message_ = now;
            self->read();
        });
    }

    static constexpr auto kRestInterval = std::chrono::microseconds(1'000'000 / kStateFrameHz);
    static constexpr auto kLiveInterval = std::chrono::microseconds(1'000'000 / kLiveFrameHz);
    static constexpr auto kKeepAliveInterval = std::chrono::microseconds(1'000'000 / kKeepAliveFrameHz);

    [[nodiscard]] bool interacting(Clock::time_point now) const { return now - last_message_ < kInteractiveWindow; }

    // One wait at a time on the frame timer. A wait cancelled because read() moved the
    // timer forward waits again for the new expiry.
    void wait() {
        if (waiting_ || closed_) return;
        waiting_ = true;
        timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
            self->waiting_ = false;
            if (self->closed_) return;
            if (ec == asio::error::operation_aborted) {
                self->wait();
                return;
            }
            self->tick();
        });
    }

    void tick() {
        const auto now = Clock::now();
        // polling only while a pointer message's force change is awaited
        const bool live = interacting(now) && session_->pointer_awaited();
        const auto since = now - last_frame_;
        // An answer waits for no frame timer; answers alone are at most kLiveFrameHz.
        const bool due = since >= kRestInterval ||
                         (live && now - last_answer_ >= kLiveInterval && session_->pointer_answer_ready());
        if (due && queue_.size() < 4) {
            bool answers_pointer = false;
            bool news = false;
            json frame = session_->state_frame(&answers_pointer, &news);
            // A frame without news (nothing the page draws moved) goes out only as the
            // keep-alive: at rest the browser has nothing to parse or redraw.
            if (news || now - last_sent_ >= kKeepAliveInterval) {
                send(frame.dump(), answers_pointer ? session_->pointer_seq() : 0);
                if (answers_pointer) last_answer_ = now;
                if (!news) session_->frame_sent_without_news();
                last_sent_ = now;
            }
            last_frame_ = now;
        }
        const auto rest = last_frame_ + kRestInterval - now;
        timer_.expires_after(live ? kLivePoll : std::max<Clock::duration>(rest, kLivePoll));
        wait();
    }

    // One message waiting to be written; a state frame that answers a pointer message
    // keeps its seq and when it was queued, so that its write time can be reported.
    struct Outgoing {
        std::string text;
        int64_t pointer_seq = 0;
        size_t ahead = 0;  // messages queued before it
        Clock::time_point queued{};
    };

    void send(std::string text, int64_t pointer_seq = 0) {
        if (closed_ || queue_.size() >= kMaxQueuedFrames) return;
        queue_.push_back(Outgoing{std::move(text), pointer_seq, queue_.size(), Clock::now()});
        if (queue_.size() == 1) write();
    }

    void write() {
        ws_.text(true);
        ws_.async_write(asio::buffer(queue_.front().text), [self = shared_from_this()](beast::error_code ec, size_t) {
            if (ec) {
                self->close();
                return;
            }
            const Outgoing& done = self->queue_.front();
            if (done.pointer_seq != 0 && self->session_) {
                self->session_->note_pointer_written(
                    done.pointer_seq, done.ahead,
                    std::chrono::duration<double, std::micro>(Clock::now() - done.queued).count());
            }
            self->queue_.pop_front();
            if (!self->queue_.empty()) self->write();
        });
    }

    void close() {
        if (closed_) return;
        closed_ = true;
        timer_.cancel();
        end_session();  // the browser's effects stop now, not when the last handler runs
    }

    void end_session() {
        if (!session_) return;
        session_.reset();
        --shared_.sessions;
    }

    websocket::stream<beast::tcp_stream> ws_;
    Request request_;  // the upgrade, alive until the handshake is done
    Shared& shared_;
    asio::steady_timer timer_;
    beast::flat_buffer buffer_;
    std::deque<Outgoing> queue_;
    std::optional<LiveSession> session_;
    bool closed_ = false;
    bool waiting_ = false;                  // a wait on timer_ is outstanding
    Clock::time_point last_frame_{};        // when the last state frame was built
    Clock::time_point last_sent_{};         // when the last state frame was queued
    Clock::time_point last_answer_{};       // when the last frame answering a pointer was queued
    Clock::time_point last_message_{};      // when the browser last sent a message
};

class HttpConnection : public std::enable_shared_from_this<HttpConnection> {
public:
    HttpConnection(tcp::socket socket, Shared& shared) : stream_(std::move(socket)), shared_(shared) {}

    void read() {
        parser_.emplace();
        parser_->body_limit(kMaxHttpBodyBytes);
        stream_.expires_after(std::chrono::seconds(30));
        http::async_read(stream_, buffer_, *parser_, [self = shared_from_this()](beast::error_code ec, size_t) {
            if (ec == http::error::body_limit) {
                Request req;
                req.version(11);
                req.keep_alive(false);
                self->respond(error_reply(req, http::status::payload_too_large,
                                          "request body larger than " + std::to_string(kMaxHttpBodyBytes) + " bytes"));
                return;
            }
            if (ec) return;
            self->handle(self->parser_->release());
        });
    }

private:
    void handle(Request req) {
        std::optional<std::string_view> origin;
        if (auto o = req.find(http::field::origin); o != req.end()) origin = sv(o->value());
        const std::string_view host = sv(req[http::field::host]);
        if (auto refusal = shared_.guard.refusal(host, origin)) {
            req.keep_alive(false);
            respond(error_reply(req, http::status::forbidden, *refusal));
            return;
        }
        if (websocket::is_upgrade(req)) {
            if (req.target() != "/live") {
                respond(error_reply(req, http::status::not_found, "the live session's WebSocket is at /live"));
                return;
            }
            stream_.expires_never();
            std::make_shared<LiveConnection>(stream_.release_socket(), shared_)->start(std::move(req));
            return;
        }
        respond(handle_http(shared_, req));
    }

    void respond(Response res) {
        auto shared_res = std::make_shared<Response>(std::move(res));
        http::async_write(stream_, *shared_res,
                          [self = shared_from_this(), shared_res](beast::error_code ec, size_t) {
                              if (ec || !shared_res->keep_alive()) {
                                  beast::error_code ignored;
                                  self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
                                  return;
                              }
                              self->read();
                          });
    }

    beast::tcp_stream stream_;
    Shared& shared_;
    beast::flat_buffer buffer_;
    std::optional<http::request_parser<http::string_body>> parser_;
};

format::SensationFile starters() {
    const Asset* a = find_data_asset("starters.feel.json");
    if (a == nullptr) throw std::runtime_error("the Studio's starters.feel.json is not embedded (build problem)");
    return format::parse_sensation_file(a->text(), "starters.feel.json");
}

}  // namespace

struct StudioServer::Impl {
    // Declared first, destroyed last: the io_context's pending handlers (and with them the
    // connections and their sessions) go before what they share.
    std::unique_ptr<Shared> shared;
    asio::io_context io{1};
    tcp::acceptor acceptor{io};
    std::thread thread;
    bool loopback = true;
    std::string listen;

    void accept() {
        acceptor.async_accept([this](beast::error_code ec, tcp::socket socket) {
            if (ec) {
                if (ec != asio::error::operation_aborted) accept();
                return;
            }
            std::make_shared<HttpConnection>(std::move(socket), *shared)->read();
            accept();
        });
    }
};

StudioServer::StudioServer(const StudioOptions& options) : impl_(std::make_unique<Impl>()) {
    Workspace workspace(options.workspace);
    beast::error_code ec;
    const asio::ip::address address = asio::ip::make_address(options.listen, ec);
    if (ec) {
        throw std::invalid_argument("--listen \"" + options.listen +
                                    "\" is not an IP address (e.g. 127.0.0.1, ::1, 192.168.1.5)");
    }
    impl_->loopback = address.is_loopback();
    impl_->listen = options.listen;
    const tcp::endpoint endpoint(address, options.port);
    impl_->acceptor.open(endpoint.protocol());
    impl_->acceptor.set_option(asio::socket_base::reuse_address(true));
    impl_->acceptor.bind(endpoint, ec);
    if (ec) {
        throw std::runtime_error("cannot listen on " + options.listen + ":" + std::to_string(options.port) + ": " +
                                 ec.message() + " (choose another --port)");
    }
    impl_->acceptor.listen(asio::socket_base::max_listen_connections);
    const uint16_t port = impl_->acceptor.local_endpoint().port();

    const format::SensationFile presets = starters();
    StudioDeviceOptions device_options;
    device_options.address = options.device;
    device_options.grip = options.grip;
    auto device = std::make_shared<StudioDevice>(device_options);
    json starter_effects = json::object();
    {
        const json file = json::parse(find_data_asset("starters.feel.json")->text());
        for (const auto& [name, effect] : file["sensations"].items()) starter_effects[name] = effect;
    }
    json hello = {{"type", "hello"},
                  {"device", device->describe()},
                  {"fields", describe_fields(presets)},
                  {"starters", starter_effects},
                  {"simulated", device->simulated()}};
    impl_->shared.reset(new Shared{std::move(workspace), std::move(device), ProtocolSchema::embedded(),
                                   RequestGuard(options.listen, port), std::move(hello)});
}

StudioServer::~StudioServer() { stop(); }

void StudioServer::start() {
    impl_->accept();
    impl_->thread = std::thread([this] { impl_->io.run(); });
}

void StudioServer::stop() {
    if (!impl_->thread.joinable()) return;
    asio::post(impl_->io, [this] {
        beast::error_code ignored;
        impl_->acceptor.close(ignored);
        impl_->io.stop();
    });
    impl_->thread.join();
}

uint16_t StudioServer::port() const noexcept {
    beast::error_code ec;
    const auto ep = impl_->acceptor.local_endpoint(ec);
    return ec ? 0 : ep.port();
}

std::string StudioServer::url() const {
    std::string host = impl_->listen;
    if (host.find(':') != std::string::npos) host = "[" + host + "]";  // IPv6
    return "http://" + host + ":" + std::to_string(port()) + "/";
}

bool StudioServer::loopback() const noexcept { return impl_->loopback; }
int StudioServer::sessions() const noexcept { return impl_->shared->sessions.load(); }

}  // namespace feel::studio
