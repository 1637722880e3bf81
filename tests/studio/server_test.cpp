// The Studio's server over real sockets: the HTTP API, the WebSocket live session, and
// every refusal of docs/studio.md "Safety" (Host, Origin, paths, sizes, malformed
// messages, a lost browser). A Beast client plays the browser.
#include <gtest/gtest.h>

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "feel/host/sensation_library.hpp"
#include "studio_server.hpp"

namespace feel::studio {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace fs = std::filesystem;
using tcp = asio::ip::tcp;
using json = nlohmann::json;

struct Reply {
    unsigned status = 0;
    std::string body;
};

class ServerTest : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() /
                ("feel-studio-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(root_);
        fs::create_directories(root_);
        StudioOptions o;
        o.workspace = root_;
        o.port = 0;
        server_ = std::make_unique<StudioServer>(o);
        server_->start();
        host_ = "127.0.0.1:" + std::to_string(server_->port());
    }
    void TearDown() override {
        server_.reset();
        fs::remove_all(root_);
    }

    Reply request(http::verb verb, const std::string& target, const std::string& body = "",
                  const std::string& host = "", const std::string& origin = "") {
        asio::io_context io;
        beast::tcp_stream s(io);
        s.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
        http::request<http::string_body> req{verb, target, 11};
        req.set(http::field::host, host.empty() ? host_ : host);
        if (!origin.empty()) req.set(http::field::origin, origin);
        req.body() = body;
        req.prepare_payload();
        http::write(s, req);
        beast::flat_buffer b;
        http::response<http::string_body> res;
        beast::error_code ec;
        http::read(s, b, res, ec);
        return {res.result_int(), res.body()};
    }
    // A request that announces a body of `length` bytes but sends only its header: the
    // server must refuse it from the header alone, without waiting for (or reading) the body.
    Reply announce_body(const std::string& target, std::size_t length) {
        asio::io_context io;
        tcp::socket s(io);
        s.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
        const std::string head = "POST " + target + " HTTP/1.1\r\nHost: " + host_ +
                                 "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(length) +
                                 "\r\n\r\n";
        asio::write(s, asio::buffer(head));
        beast::flat_buffer b;
        http::response<http::string_body> res;
        beast::error_code ec;
        http::read(s, b, res, ec);
        return {res.result_int(), res.body()};
    }
    Reply api(const std::string& call, const json& body) { return request(http::verb::post, "/api/" + call, body.dump()); }

    std::unique_ptr<websocket::stream<tcp::socket>> open_live(const std::string& origin = "") {
        auto ws = std::make_unique<websocket::stream<tcp::socket>>(io_);
        ws->next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
        ws->set_option(websocket::stream_base::decorator([origin](websocket::request_type& r) {
            if (!origin.empty()) r.set(http::field::origin, origin);
        }));
        ws->handshake(host_, "/live");
        return ws;
    }
    static json next(websocket::stream<tcp::socket>& ws, const std::string& type) {
        for (int i = 0; i < 500; ++i) {
            beast::flat_buffer b;
            ws.read(b);
            json m = json::parse(beast::buffers_to_string(b.data()));
            if (m["type"] == type) return m;
        }
        return {};
    }

    fs::path root_;
    std::unique_ptr<StudioServer> server_;
    std::string host_;
    asio::io_context io_;
};

TEST_F(ServerTest, ServesTheEmbeddedPageAndTheProtocol) {
    const Reply page = request(http::verb::get, "/");
    EXPECT_EQ(page.status, 200u);
    EXPECT_NE(page.body.find("feel Studio"), std::string::npos);
    const Reply protocol = request(http::verb::get, "/protocol.json");
    EXPECT_EQ(protocol.status, 200u);
    EXPECT_TRUE(json::parse(protocol.body).contains("client"));
    EXPECT_EQ(request(http::verb::get, "/nothing-here").status, 404u);
}

TEST_F(ServerTest, RefusesWrongHostAndOriginOnRequestsAndUpgrades) {
    EXPECT_EQ(request(http::verb::get, "/", "", "rebound.example:" + std::to_string(server_->port())).status, 403u);
    const Reply evil = request(http::verb::post, "/api/list", "{}", "", "http://evil.example");
    EXPECT_EQ(evil.status, 403u);
    EXPECT_NE(evil.body.find("Origin"), std::string::npos);
    EXPECT_THROW((void)open_live("http://evil.example"), boost::system::system_error);
    EXPECT_NO_THROW((void)open_live("http://" + host_));
}

TEST_F(ServerTest, RefusesPathsOutsideTheWorkspace) {
    for (const char* p : {"../x.feel.json", "/etc/passwd.feel.json", "a/../../x.feel.json"}) {
        const Reply r = api("read", {{"path", p}});
        EXPECT_EQ(r.status, 403u) << p;
        EXPECT_TRUE(json::parse(r.body).contains("error"));
    }
    fs::create_directory_symlink(fs::temp_directory_path(), root_ / "out");
    EXPECT_EQ(api("save", {{"path", "out/x.feel.json"}, {"text", "{}"}}).status, 403u);
}

// A file that is not there is not a refusal: 404 with a sentence naming it (the favorites
// file before the first favorite is saved), while a path that leads out stays 403.
TEST_F(ServerTest, AMissingFileIsNotFoundNotForbidden) {
    const Reply favorites = api("read", {{"path", "favorites.feel.json"}});
    EXPECT_EQ(favorites.status, 404u) << favorites.body;
    EXPECT_EQ(json::parse(favorites.body)["error"], "path \"favorites.feel.json\": no such file in the workspace");
    EXPECT_EQ(api("read", {{"path", "no/such/folder.feel.json"}}).status, 404u);
    EXPECT_EQ(api("copy", {{"from", "gone.feel.json"}, {"to", "copy.feel.json"}}).status, 404u);
    EXPECT_EQ(api("rename", {{"from", "gone.feel.json"}, {"to", "moved.feel.json"}}).status, 404u);
    fs::create_directory_symlink(fs::temp_directory_path(), root_ / "out");
    const Reply out = api("read", {{"path", "out/favorites.feel.json"}});
    EXPECT_EQ(out.status, 403u) << out.body;
    EXPECT_NE(out.body.find("leads out"), std::string::npos) << out.body;
    // Once saved, it reads.
    const std::string text = R"({"format": "feel/1", "sensations": {"My_Favorites.soft": {"type": "spring",
      "duration_us": "infinite", "axes": ["x"], "conditions": [{"pos_coefficient": 2000, "neg_coefficient": 2000}]}}})";
    ASSERT_EQ(api("save", {{"path", "favorites.feel.json"}, {"text", text}}).status, 200u);
    EXPECT_EQ(api("read", {{"path", "favorites.feel.json"}}).status, 200u);
}

TEST_F(ServerTest, BoundsBodiesAndAnswersMalformedRequests) {
    EXPECT_EQ(request(http::verb::post, "/api/read", "not json").status, 400u);
    EXPECT_EQ(request(http::verb::post, "/api/list", "[1]").status, 400u);
    EXPECT_EQ(request(http::verb::get, "/api/list").status, 405u);
    EXPECT_EQ(api("nonsense", json::object()).status, 404u);
    // Announced from the header alone: sending the whole body would race the server's close
    // (the client's write then fails with a broken pipe before it reads the answer).
    EXPECT_EQ(announce_body("/api/save", kMaxHttpBodyBytes + 10).status, 413u);
    const Reply bad = api("save", {{"path", "bad.feel.json"}, {"text", R"({"format": "feel/1", "sensations": {}})"}});
    EXPECT_EQ(bad.status, 422u);
}

TEST_F(ServerTest, SavedFilesLoadAndPlayWithSensationLibraryInTwoCalls) {
    const std::string text = R"({"format": "feel/1", "sensations": {"hum": {"type": "sine", "duration_us": 200000,
      "axes": ["x"], "trigger_button": 2, "periodic": {"magnitude": 3000, "period_us": 10000}}}})";
    const Reply saved = api("save", {{"path", "hum.feel.json"}, {"text", text}});
    ASSERT_EQ(saved.status, 200u) << saved.body;
    auto library = host::SensationLibrary::load(root_ / "hum.feel.json");
    ASSERT_TRUE(library) << library.status().message;
    EXPECT_TRUE(library->play("hum").ok());
    EXPECT_EQ(library->effects("hum")[0].parameters().trigger.index, 2);
}

TEST_F(ServerTest, LiveSessionAnswersMalformedMessagesAndAppliesValidSensations) {
    auto ws = open_live();
    const json hello = next(*ws, "hello");
    EXPECT_EQ(hello["device"]["name"], "iforce2");
    EXPECT_EQ(hello["fields"]["types"].size(), 33u);
    // the input scales the condition editors plot against (docs/conditions.md: the stick's
    // velocity_ref is 1e5 units/s, its acceleration_ref that speed reached in 50 ms)
    EXPECT_DOUBLE_EQ(hello["device"]["velocity_ref"].get<double>(), 1e5);
    EXPECT_DOUBLE_EQ(hello["device"]["acceleration_ref"].get<double>(), 1e5 / 0.05);
    for (const std::string bad : {"{", "[]", R"({"type": "nope"})", R"({"type": "pointer", "seq": 1, "x": 20000, "y": 0})",
                                  R"({"type": "play"})", R"({"type": "gain", "gain": 1.5})",
                                  R"({"type": "stop_all", "extra": 1})"}) {
        ws->write(asio::buffer(bad));
        const json e = next(*ws, "error");
        EXPECT_NE(e["message"].get<std::string>().find("malformed"), std::string::npos) << bad << " -> " << e;
    }
    // An invalid sensation: the format's message at its field, and nothing reaches the device.
    json msg = {{"type", "set_sensation"}, {"seq", 1}, {"name", "s"}, {"file", "s.feel.json"},
                {"effects", json::array({json{{"type", "sine"}, {"duration_us", 1000000}, {"axes", {"x"}},
                                              {"periodic", {{"magnitude", 20000}, {"period_us", 10000}}}}})}};
    ws->write(asio::buffer(msg.dump()));
    json v = next(*ws, "validated");
    EXPECT_FALSE(v["ok"].get<bool>());
    EXPECT_EQ(v["errors"][0]["field"], "periodic.magnitude");
    EXPECT_EQ(v["errors"][0]["message"],
              "s.feel.json: sensation \"s\": periodic.magnitude = 20000 is out of range (allowed 0..10000)");
    msg["seq"] = 2;
    msg["effects"][0]["type"] = "square";  // its peaks are flat: any sample of one is the magnitude
    msg["effects"][0]["periodic"]["magnitude"] = 5000;
    ws->write(asio::buffer(msg.dump()));
    v = next(*ws, "validated");
    EXPECT_TRUE(v["ok"].get<bool>()) << v;
    ws->write(asio::buffer(json{{"type", "play"}, {"effect", 0}}.dump()));
    // The wave shows in the state frames.
    // Frames come faster while the browser interacts: wait on time, not on a frame count.
    double peak = 0;
    for (const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
         std::abs(peak - 5000) > 150 && std::chrono::steady_clock::now() < end;) {
        const json s = next(*ws, "state");
        for (const json& row : s["samples"]) peak = std::max(peak, std::abs(row[1].get<double>()));
    }
    EXPECT_NEAR(peak, 5000, 150);
}

TEST_F(ServerTest, ALostBrowserStopsItsEffects) {
    auto ws = open_live();
    (void)next(*ws, "hello");
    const json msg = {{"type", "set_sensation"}, {"seq", 1}, {"name", "c"},
                      {"effects", json::array({json{{"type", "constant"}, {"duration_us", "infinite"}, {"axes", {"x"}},
                                                    {"constant", {{"magnitude", 4000}}}}})}};
    ws->write(asio::buffer(msg.dump()));
    ASSERT_TRUE(next(*ws, "validated")["ok"].get<bool>());
    ws->write(asio::buffer(json{{"type", "play"}, {"effect", 0}}.dump()));
    double force = 0;
    for (const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
         std::abs(force - 4000) > 1 && std::chrono::steady_clock::now() < end;) {
        const json s = next(*ws, "state");
        if (!s["force"].empty()) force = s["force"][0].get<double>();
    }
    EXPECT_NEAR(force, 4000, 1);  // a constant force, as the device reports it
    ws->next_layer().close();  // the browser goes away without a goodbye
    ws.reset();
    for (int i = 0; i < 100 && server_->sessions() > 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_EQ(server_->sessions(), 0);
    auto watcher = open_live();
    (void)next(*watcher, "hello");
    double after = 1e9;
    for (const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
         std::chrono::steady_clock::now() < end;) {
        const json s = next(*watcher, "state");
        if (!s["force"].empty()) after = s["force"][0].get<double>();
    }
    EXPECT_NEAR(after, 0, 1);
}

TEST_F(ServerTest, RefusesOversizedWebSocketMessages) {
    auto ws = open_live();
    (void)next(*ws, "hello");
    const std::string huge(kMaxWebSocketMessageBytes + 100, ' ');
    beast::error_code ec;
    ws->write(asio::buffer(huge), ec);
    beast::flat_buffer b;
    for (int i = 0; i < 500 && !ec; ++i) ws->read(b, ec), b.consume(b.size());
    EXPECT_TRUE(ec) << "the server closed the connection";
}

// A dynamic that asks for interim reports (§5.2) has them in the state frames, at the
// rate the device announces, with the mass's offset per axis of the effect; one that does
// not ask has none.
TEST_F(ServerTest, APointerMoveIsTimedHopByHop) {
    auto ws = open_live();
    (void)next(*ws, "hello");
    const json condition = {{"pos_coefficient", 5000}, {"neg_coefficient", 5000}};
    const json spring = {{"type", "spring"}, {"duration_us", "infinite"}, {"axes", {"x", "y"}},
                         {"conditions", {condition, condition}}};
    ws->write(asio::buffer(json{{"type", "set_sensation"}, {"seq", 1}, {"name", "s"}, {"effects", {spring}}}.dump()));
    ASSERT_TRUE(next(*ws, "validated")["ok"].get<bool>());
    ws->write(asio::buffer(json{{"type", "play"}, {"effect", 0}}.dump()));
    // Until the spring plays (its state in the frames), then the pointer to +6000.
    for (const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
         std::chrono::steady_clock::now() < end;) {
        const json st = next(*ws, "state");
        if (!st["effects"].empty() && st["effects"][0]["state"] == "playing") break;
    }
    ws->write(asio::buffer(json{{"type", "pointer"}, {"seq", 7}, {"x", 6000}, {"y", 0}}.dump()));
    json hops, written, shown;
    for (const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
         written.is_null() && std::chrono::steady_clock::now() < end;) {
        const json st = next(*ws, "state");
        EXPECT_EQ(st["dropped_reports"], 0);
        EXPECT_EQ(st["position"].size(), 2u);  // every frame has the state, news or not
        if (st.contains("pointer_hops")) {
            EXPECT_TRUE(hops.is_null()) << "one frame answers a pointer message: " << st["pointer_hops"];
            hops = st["pointer_hops"];
            shown = st;
        }
        if (st.contains("pointer_written")) written = st["pointer_written"];
    }
    ASSERT_FALSE(hops.is_null());
    EXPECT_EQ(hops["seq"], 7);
    // The frame that answers shows the spring pulling back toward the centre (§3.1: the
    // force opposes the displacement), the handle on its way to +6000.
    EXPECT_GT(shown["position"][0].get<double>(), 0);
    EXPECT_LT(shown["force"][0].get<double>(), -20);
    for (const char* k : {"apply_us", "device_us", "frame_us"}) EXPECT_GE(hops[k].get<double>(), 0) << k;
    // The hops add up to the span between the read and the frame on the other clock.
    const double span = hops["built_wall_us"].get<double>() - hops["read_wall_us"].get<double>();
    const double sum = hops["apply_us"].get<double>() + hops["device_us"].get<double>() + hops["frame_us"].get<double>();
    EXPECT_NEAR(span, sum, 1000) << hops;
    // The device's software path ends at the report of the tick that took the target, which
    // is at or before the tick whose force moved (the hand had to move the handle first).
    EXPECT_GE(hops["software_us"].get<double>(), 0) << hops;
    EXPECT_LE(hops["software_us"].get<double>(), hops["device_us"].get<double>()) << hops;
    ASSERT_FALSE(written.is_null());
    EXPECT_EQ(written["seq"], 7);
    EXPECT_GE(written["write_us"].get<double>(), 0);
}

TEST_F(ServerTest, StateFramesCarryADynamicsInterimReports) {
    auto ws = open_live();
    const json hello = next(*ws, "hello");
    const double hz = hello["device"]["interim_report_hz"].get<double>();
    ASSERT_GT(hz, 0);
    json recoil = {{"type", "dynamic_recoil"}, {"duration_us", 1000000}, {"axes", {"x", "y"}},
                   {"dynamic", {{"blast_direction", 18000}, {"blast_intensity", 8000}, {"dynamic_mass", 500},
                                {"blast_resonance", 3000}, {"blast_decay", 200}}}};
    for (const bool interim : {false, true}) {  // the same effect, updated in place
        recoil["dynamic"]["interim_reporting"] = interim;
        ws->write(asio::buffer(json{{"type", "set_sensation"}, {"seq", interim ? 2 : 1}, {"name", "r"},
                                    {"effects", json::array({recoil})}}.dump()));
        ASSERT_TRUE(next(*ws, "validated")["ok"].get<bool>());
        ws->write(asio::buffer(json{{"type", "play"}, {"effect", 0}}.dump()));
        // Until the session has seen the play end (a loaded machine may start it late).
        std::vector<json> reports;
        bool played = false;
        for (const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
             std::chrono::steady_clock::now() < end;) {
            const json st = next(*ws, "state");
            for (const json& r : st["dynamics"]) reports.push_back(r);
            const json& e = st["effects"];
            if (!e.empty() && e[0]["starts"] == (interim ? 2 : 1)) {
                if (e[0]["state"] == "playing") played = true;
                else if (played) break;
            }
        }
        ASSERT_TRUE(played);
        if (!interim) {
            EXPECT_TRUE(reports.empty()) << reports.front();
            continue;
        }
        ASSERT_GT(reports.size(), 20u);
        for (const json& r : reports) {
            EXPECT_EQ(r["effect"], 0);
            EXPECT_EQ(r["kind"], "interim");
            EXPECT_EQ(r["position"].size(), 2u);
        }
        const double span_ms = reports.back()["t_ms"].get<double>() - reports.front()["t_ms"].get<double>();
        EXPECT_NEAR(static_cast<double>(reports.size() - 1) * 1000.0 / span_ms, hz, 0.1 * hz);
        // the blast from 180° kicks the mass along y, not x
        double peak_x = 0, peak_y = 0;
        for (const json& r : reports) {
            peak_x = std::max(peak_x, std::abs(r["position"][0].get<double>()));
            peak_y = std::max(peak_y, std::abs(r["position"][1].get<double>()));
        }
        EXPECT_GT(peak_y, 10.0);
        EXPECT_LT(peak_x, 0.01 * peak_y);
    }
}

}  // namespace
}  // namespace feel::studio
