// `feel device --sim` as its own process, like a peripheral on a cable: the real binary is
// started as a child, the host commands (run as the binary too) open it over a Unix socket
// and over TCP on loopback, and SIGTERM stops it cleanly (exit 0, its socket removed).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "cli_fixture.hpp"

namespace feel::cli::testing {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

const std::string kFeel = FEEL_EXECUTABLE;

// A child process running the feel binary, its stdout and stderr into one pipe.
class Child {
public:
    explicit Child(const std::vector<std::string>& args) {
        int fds[2];
        if (::pipe(fds) != 0) return;
        pid_ = ::fork();
        if (pid_ == 0) {
            ::dup2(fds[1], STDOUT_FILENO);
            ::dup2(fds[1], STDERR_FILENO);
            ::close(fds[0]);
            ::close(fds[1]);
            std::vector<char*> argv;
            argv.push_back(const_cast<char*>(kFeel.c_str()));
            for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            ::execv(kFeel.c_str(), argv.data());
            ::_exit(127);
        }
        ::close(fds[1]);
        out_fd_ = fds[0];
        ::fcntl(out_fd_, F_SETFL, ::fcntl(out_fd_, F_GETFL) | O_NONBLOCK);
    }
    ~Child() {
        if (pid_ > 0 && !exited_) {
            ::kill(pid_, SIGKILL);
            int status = 0;
            ::waitpid(pid_, &status, 0);
        }
        if (out_fd_ >= 0) ::close(out_fd_);
    }
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;

    [[nodiscard]] bool started() const { return pid_ > 0; }
    // What it printed so far.
    const std::string& output() {
        std::array<char, 4096> buf{};
        for (;;) {
            const ssize_t n = ::read(out_fd_, buf.data(), buf.size());
            if (n <= 0) break;
            out_.append(buf.data(), static_cast<size_t>(n));
        }
        return out_;
    }
    // Whether it is still running.
    bool running() {
        if (exited_) return false;
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_) {
            exited_ = true;
            code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
        }
        return !exited_;
    }
    // Sends `signal` and waits up to `limit` for the exit; its exit code, or -1000 if it
    // did not exit (then it is killed), -N if signal N ended it.
    int stop(int signal, std::chrono::milliseconds limit) {
        ::kill(pid_, signal);
        const auto deadline = std::chrono::steady_clock::now() + limit;
        while (running()) {
            if (std::chrono::steady_clock::now() > deadline) return -1000;
            std::this_thread::sleep_for(10ms);
        }
        return code_;
    }

private:
    pid_t pid_ = -1;
    int out_fd_ = -1;
    std::string out_;
    bool exited_ = false;
    int code_ = -1;
};

struct Process {
    int code = -1;
    std::string out;  // stdout and stderr
};

Process feel(const std::string& args) {
    Process r;
    FILE* pipe = ::popen(("'" + kFeel + "' " + args + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return r;
    std::array<char, 4096> buf{};
    while (size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) r.out.append(buf.data(), n);
    const int status = ::pclose(pipe);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// A TCP port on loopback that nothing listens on now (the kernel's pick for port 0).
int free_tcp_port() {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = 0;
    socklen_t len = sizeof addr;
    int port = -1;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0 &&
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) == 0) {
        port = ntohs(addr.sin_port);
    }
    ::close(fd);
    return port;
}

// Waits until `ready()` or the child exits or 5 s pass.
template <class Ready>
bool wait_for(Child& child, Ready ready) {
    const auto deadline = std::chrono::steady_clock::now() + 5s;
    while (std::chrono::steady_clock::now() < deadline) {
        if (ready()) return true;
        if (!child.running()) return false;
        std::this_thread::sleep_for(20ms);
    }
    return false;
}

class DeviceProcess : public CliTest {
protected:
    // A short socket path: sun_path holds 108 bytes.
    std::string socket_path() const {
        return (fs::temp_directory_path() / ("feel-cli-test-" + std::to_string(::getpid()) + ".sock")).string();
    }
    std::string sample_path() {
        const std::string file = path("effects.feel.json");
        write(file, format::write_sensation_file(sample_file()));
        return file;
    }
    // Caps and play against the device at `address`, as the binary.
    void use_device(const std::string& address, const std::string& profile) {
        const Process caps = feel("caps --device " + address);
        EXPECT_EQ(caps.code, 0) << caps.out;
        EXPECT_TRUE(std::regex_search(caps.out, std::regex("(^|\n)device: +" + profile + "\n"))) << caps.out;
        EXPECT_NE(caps.out.find("address:           " + address), std::string::npos) << caps.out;
        // The same capabilities as the in-process device of the profile, line for line
        // (but the address).
        const Process local = feel("caps --device sim:" + profile);
        EXPECT_EQ(caps.out.substr(0, caps.out.find("address:")), local.out.substr(0, local.out.find("address:")));

        const Process play = feel("play '" + sample_path() + "' --sensation push_west --device " + address);
        EXPECT_EQ(play.code, 0) << play.out;
        EXPECT_NE(play.out.find("on         " + address), std::string::npos) << play.out;
        EXPECT_TRUE(std::regex_search(play.out, std::regex(R"(\nx +-216[0-1]\.[0-9] )"))) << play.out;
        EXPECT_NE(play.out.find("ended      after "), std::string::npos) << play.out;
    }
};

TEST_F(DeviceProcess, ServesHostsOnAUnixSocketAndStopsOnSigterm) {
    const std::string sock = socket_path();
    fs::remove(sock);
    Child device({"device", "--sim", "--profile", "joystick", "--listen", "unix:" + sock});
    ASSERT_TRUE(device.started());
    ASSERT_TRUE(wait_for(device, [&] { return fs::exists(sock); })) << device.output();
    EXPECT_TRUE(wait_for(device, [&] { return device.output().find("unix:" + sock) != std::string::npos; }))
        << device.output();

    use_device("unix:" + sock, "joystick");
    // feel devices finds it in its socket directory.
    const Process devices = feel("devices --socket-dir " + fs::path(sock).parent_path().string());
    EXPECT_EQ(devices.code, 0) << devices.out;
    EXPECT_TRUE(std::regex_search(devices.out, std::regex("\nunix:" + sock + " +joystick +I-FORCE 2\\.0"))) << devices.out;

    EXPECT_EQ(device.stop(SIGTERM, 5000ms), 0) << device.output();
    EXPECT_FALSE(fs::exists(sock)) << "the socket file is left behind";
}

TEST_F(DeviceProcess, ServesHostsOverTcpAndStopsOnSigint) {
    // A port nobody uses now; another process may take it before the device binds it, so
    // try a few.
    for (int attempt = 0; attempt < 5; ++attempt) {
        const int port = free_tcp_port();
        ASSERT_GT(port, 0);
        const std::string address = "tcp:127.0.0.1:" + std::to_string(port);
        Child device({"device", "--sim", "--listen", address});
        ASSERT_TRUE(device.started());
        const bool up = wait_for(device, [&] { return device.output().find(address) != std::string::npos; });
        if (!up && !device.running()) continue;  // the port was taken: another one
        ASSERT_TRUE(up) << device.output();
        use_device(address, "iforce2");
        EXPECT_EQ(device.stop(SIGINT, 5000ms), 0) << device.output();
        return;
    }
    FAIL() << "no free TCP port in 5 attempts";
}

TEST_F(DeviceProcess, BadListenAddressesExitTwo) {
    for (const char* bad : {"tcp:localhost", "unix:", "tcp:127.0.0.1:70000"}) {
        const Process r = feel(std::string("device --sim --listen '") + bad + "'");
        EXPECT_EQ(r.code, 2) << bad << ": " << r.out;
        EXPECT_NE(r.out.find("--listen"), std::string::npos) << r.out;
    }
}

TEST_F(DeviceProcess, HostCommandsExitTwoForAddressesThatAreNotAddressesAndOneForNobody) {
    for (const char* bad : {"tcp:localhost", "unix:", "tcp:127.0.0.1:0", "sim:nope"}) {
        const Process r = feel(std::string("caps --device '") + bad + "'");
        EXPECT_EQ(r.code, 2) << bad << ": " << r.out;
        EXPECT_NE(r.out.find("--device"), std::string::npos) << r.out;
    }
    const std::string nobody =
        (fs::temp_directory_path() / ("feel-cli-nobody-" + std::to_string(::getpid()) + ".sock")).string();
    fs::remove(nobody);
    const Process r = feel("caps --device unix:" + nobody);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find(nobody), std::string::npos) << r.out;
}

}  // namespace
}  // namespace feel::cli::testing
