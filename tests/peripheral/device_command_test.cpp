// `feel device --sim`: run_device() in process, stopped by its flag as the CLI's SIGINT and
// SIGTERM handlers stop it. (The signal path itself is the CLI's, tested with the binary.)
#include "device_command.hpp"

#include <gtest/gtest.h>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "cli.hpp"
#include "session_rig.hpp"

namespace feel::cli {
namespace {

using namespace std::chrono_literals;

std::filesystem::path temp_dir(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("feel-device-test-" + std::to_string(::getpid()) + "-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

bool wait_for_file(const std::filesystem::path& path) {
    for (int i = 0; i < 500; ++i) {
        if (std::filesystem::exists(path)) return true;
        std::this_thread::sleep_for(10ms);
    }
    return false;
}

std::string usage_error(const DeviceArgs& args) {
    std::ostringstream out, err;
    std::atomic<bool> stop{true};
    try {
        (void)run_device(args, out, err, stop);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(DeviceCommand, RequiresSim) {
    DeviceArgs args;
    const std::string message = usage_error(args);
    EXPECT_NE(message.find("--sim"), std::string::npos) << message;
    EXPECT_NE(message.find("only simulated devices"), std::string::npos) << message;
}

TEST(DeviceCommand, NamesTheWrongOption) {
    DeviceArgs args;
    args.sim = true;
    args.profile = "gamepad";
    EXPECT_NE(usage_error(args).find("--profile \"gamepad\" is not a known device (available: joystick"),
              std::string::npos);
    args.profile = "iforce1";
    args.rate_hz = 1500;  // beyond the I-FORCE 1.x class's 1 kHz
    EXPECT_NE(usage_error(args).find("--rate = 1500 Hz is out of range"), std::string::npos) << usage_error(args);
    args.rate_hz = 999.5;
    EXPECT_NE(usage_error(args).find("whole number"), std::string::npos);
    args.rate_hz = 0;
    args.hand = "claw";
    EXPECT_NE(usage_error(args).find("--hand \"claw\""), std::string::npos);
    args.hand = "firm";
    args.motion = "sine:x:20000:1";
    EXPECT_NE(usage_error(args).find("--motion"), std::string::npos);
    args.motion = "hold:0";
    args.listen = "sim:iforce1";
    EXPECT_NE(usage_error(args).find("--listen"), std::string::npos);
    args.listen = "carrier-pigeon:coop";
    EXPECT_NE(usage_error(args).find("--listen"), std::string::npos);
}

TEST(DeviceCommand, ServesUntilStoppedThenRemovesItsSocket) {
    const std::filesystem::path dir = temp_dir("serve");
    const std::filesystem::path socket = dir / "dev.sock";
    DeviceArgs args;
    args.sim = true;
    args.profile = "iforce1";
    args.listen = "unix:" + socket.string();
    std::ostringstream out, err;
    std::atomic<bool> stop{false};
    int rc = -1;
    std::thread device([&] { rc = run_device(args, out, err, stop); });
    ASSERT_TRUE(wait_for_file(socket));
    {
        auto host = transport::connect(transport::Address::parse(args.listen), 2s);
        host->send(peripheral::test::get_feature(protocol::ReportId::device_info));
        std::optional<protocol::DeviceInfoReport> info;
        // Until the reply, among the state reports the device sends meanwhile (as many as
        // the machine's load lets through before it): a deadline, not a count of frames.
        const auto until = std::chrono::steady_clock::now() + 10s;
        while (!info && std::chrono::steady_clock::now() < until) {
            const auto f = host->receive(50ms);
            protocol::AnyReport r;
            if (f && f->kind == transport::FrameKind::feature_reply && protocol::decode(f->payload, r).ok()) {
                if (const auto* d = std::get_if<protocol::DeviceInfoReport>(&r)) info = *d;
            }
        }
        ASSERT_TRUE(info.has_value());
        EXPECT_STREQ(info->device, "iforce1");
    }
    stop = true;
    device.join();
    EXPECT_EQ(rc, kExitOk);
    EXPECT_FALSE(std::filesystem::exists(socket));
    const std::string text = out.str();
    EXPECT_NE(text.find("feel device: iforce1 (I-FORCE 1.x) listening on unix:" + socket.string() + ", loop 1000 Hz\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("feel device: stopped after"), std::string::npos) << text;
    EXPECT_NE(text.find("1 host served"), std::string::npos) << text;
    std::filesystem::remove_all(dir);
}

TEST(DeviceCommand, DefaultSocketIsPerProfileInAPrivateDirectory) {
    const std::filesystem::path runtime_dir = temp_dir("xdg");
    const char* previous = std::getenv("XDG_RUNTIME_DIR");
    const std::optional<std::string> saved = previous ? std::optional<std::string>(previous) : std::nullopt;
    ::setenv("XDG_RUNTIME_DIR", runtime_dir.c_str(), 1);
    const std::filesystem::path socket = runtime_dir / "feel" / "iforce2.sock";
    EXPECT_EQ(default_device_address("iforce2"), "unix:" + socket.string());

    DeviceArgs args;
    args.sim = true;
    args.rate_hz = 500;
    std::ostringstream out, err;
    std::atomic<bool> stop{false};
    int rc = -1;
    std::thread device([&] { rc = run_device(args, out, err, stop); });
    const bool listening = wait_for_file(socket);
    stop = true;
    device.join();
    if (saved) ::setenv("XDG_RUNTIME_DIR", saved->c_str(), 1); else ::unsetenv("XDG_RUNTIME_DIR");
    ASSERT_TRUE(listening);
    EXPECT_EQ(rc, kExitOk);
    struct stat st {};
    ASSERT_EQ(::stat((runtime_dir / "feel").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0700u);
    EXPECT_NE(out.str().find("iforce2 (I-FORCE 2.0) listening on unix:" + socket.string() + ", loop 500 Hz"),
              std::string::npos)
        << out.str();
    EXPECT_FALSE(std::filesystem::exists(socket));
    std::filesystem::remove_all(runtime_dir);
}


TEST(DeviceCommand, AnOpenDefaultSocketDirIsReplacedByAPrivateOneWithAWarning) {
    const std::filesystem::path runtime_dir = temp_dir("xdg-open");
    const char* previous = std::getenv("XDG_RUNTIME_DIR");
    const std::optional<std::string> saved = previous ? std::optional<std::string>(previous) : std::nullopt;
    ::setenv("XDG_RUNTIME_DIR", runtime_dir.c_str(), 1);
    const std::filesystem::path open_dir = runtime_dir / "feel";
    std::filesystem::create_directories(open_dir);
    ::chmod(open_dir.c_str(), 0777);  // someone else may put a socket of theirs here

    DeviceArgs args;
    args.sim = true;
    std::ostringstream out, err;
    std::atomic<bool> stop{false};
    int rc = -1;
    std::thread device([&] { rc = run_device(args, out, err, stop); });
    // The fresh directory is made beside the open one: <runtime dir>/feel-XXXXXX.
    bool listening = false;
    for (int i = 0; i < 500 && !listening; ++i) {
        for (const auto& entry : std::filesystem::directory_iterator(runtime_dir)) {
            if (entry.path() != open_dir && std::filesystem::exists(entry.path() / "iforce2.sock")) listening = true;
        }
        std::this_thread::sleep_for(10ms);
    }
    stop = true;
    device.join();
    if (saved) ::setenv("XDG_RUNTIME_DIR", saved->c_str(), 1); else ::unsetenv("XDG_RUNTIME_DIR");
    ASSERT_TRUE(listening);
    EXPECT_EQ(rc, kExitOk);
    EXPECT_NE(err.str().find("is not private (its mode is 0777, not 0700)"), std::string::npos) << err.str();
    EXPECT_EQ(out.str().find("listening on unix:" + (open_dir / "iforce2.sock").string()), std::string::npos)
        << out.str();
    EXPECT_NE(out.str().find("listening on unix:" + open_dir.string() + "-"), std::string::npos) << out.str();
    std::filesystem::remove_all(runtime_dir);
}

TEST(DeviceCommand, BeyondLoopbackNeedsAllowRemoteAndAPrivateTokenFile) {
    DeviceArgs args;
    args.sim = true;
    args.listen = "tcp:0.0.0.0:0";
    EXPECT_NE(usage_error(args).find("is not a loopback address"), std::string::npos) << usage_error(args);
    args.allow_remote = true;
    ::unsetenv("FEEL_DEVICE_TOKEN");
    EXPECT_NE(usage_error(args).find("--allow-remote needs a token"), std::string::npos) << usage_error(args);

    const std::filesystem::path dir = temp_dir("token");
    const std::filesystem::path token = dir / "token";
    {
        std::ofstream file(token);
        file << "Sesame-42\n";
    }
    ::chmod(token.c_str(), 0644);
    args.token_file = token.string();
    EXPECT_NE(usage_error(args).find("may be read by others"), std::string::npos) << usage_error(args);
    ::chmod(token.c_str(), 0600);

    // With all three: it listens, warns, and a host must present the token. The port is
    // one the system just gave out as free.
    const std::string port = std::to_string(transport::listen(transport::Address::parse_listen("tcp:127.0.0.1:0"))
                                                ->address()
                                                .port);
    args.listen = "tcp:0.0.0.0:" + port;
    std::ostringstream out, err;
    std::atomic<bool> stop{false};
    int rc = -1;
    std::thread device([&] { rc = run_device(args, out, err, stop); });
    std::unique_ptr<transport::Connection> with;
    for (int i = 0; i < 500 && !with; ++i) {
        try {
            with = transport::connect(transport::Address::parse("tcp:127.0.0.1:" + port + "?token=Sesame-42"), 2s);
        } catch (const transport::TransportError&) {
            std::this_thread::sleep_for(10ms);
        }
    }
    std::optional<transport::Frame> f;
    if (with) {
        with->send(transport::Frame{transport::FrameKind::get_descriptor, {}});
        while ((f = with->receive(2s)) && f->kind == transport::FrameKind::input_report) {
        }
        with->close();
    }
    stop = true;
    device.join();
    ASSERT_NE(with, nullptr);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->kind, transport::FrameKind::descriptor_reply);
    EXPECT_EQ(rc, kExitOk);
    EXPECT_NE(err.str().find("warning: listening on tcp:0.0.0.0:"), std::string::npos) << err.str();
    std::filesystem::remove_all(dir);
}

TEST(DeviceCommand, GroupIsForUnixSocketsAndMustExist) {
    DeviceArgs args;
    args.sim = true;
    args.listen = "tcp:127.0.0.1:0";
    args.group = "root";
    EXPECT_NE(usage_error(args).find("--group is for a unix: socket"), std::string::npos) << usage_error(args);
    args.listen = "unix:/tmp/feel-group-test.sock";
    args.group = "no-such-group-feel";
    EXPECT_NE(usage_error(args).find("is not a group"), std::string::npos) << usage_error(args);
}

}  // namespace
}  // namespace feel::cli
