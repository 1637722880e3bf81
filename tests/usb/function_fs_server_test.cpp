// FunctionFsServer's shutdown, without a VM: stop() returns within a bounded time whatever
// the host does, because no endpoint submission waits inside the kernel.
//
// The stand-in for a FunctionFS instance: ep0 is a pseudo-terminal in raw mode (what the
// server writes to ep0, its descriptors, comes out at the master and stays there; the
// events the test writes to the master are what the server reads from ep0), ep1 and ep2 are
// FIFOs. A FIFO takes Linux AIO the way a FunctionFS endpoint that is not enabled does: the
// submission runs inside io_submit() and waits there, for data (OUT) or for room (IN),
// unless the file is O_NONBLOCK (pipe_read/pipe_write, as f_fs.c's ffs_epfile_io waits for
// the endpoint to be enabled). That wait is how `feel device --usb` once missed its SIGTERM
// in the VM (docs/usb-device.md, "Stopping"): the gadget unbound, an IN report submitted
// before the DISABLE event was read, the I/O thread asleep in io_submit() and stop()
// joining it forever. The kernel side, with a real host, is `make test-linux`'s.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <linux/usb/functionfs.h>
#include <stdlib.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <future>
#include <string>
#include <thread>

#include "feel/peripheral/peripheral.hpp"
#include "feel/usb/usb_device.hpp"

namespace feel::usb {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

// stop() must return within this; its loop wakes at least every 100 ms.
constexpr auto kStopBound = 2s;

class FakeFunctionFs {
public:
    FakeFunctionFs() {
        char dir_template[] = "/tmp/feel-ffs-XXXXXX";
        if (::mkdtemp(dir_template) == nullptr) return;
        dir_ = dir_template;
        master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
        if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0) return;
        const char* slave_name = ::ptsname(master_);
        if (slave_name == nullptr) return;
        // Raw before the server opens it: its descriptors and our events pass as bytes.
        slave_ = ::open(slave_name, O_RDWR | O_NOCTTY);
        termios raw{};
        if (slave_ < 0 || ::tcgetattr(slave_, &raw) != 0) return;
        ::cfmakeraw(&raw);
        if (::tcsetattr(slave_, TCSANOW, &raw) != 0) return;
        if (::symlink(slave_name, (dir_ / "ep0").c_str()) != 0) return;
        if (::mkfifo((dir_ / "ep1").c_str(), 0600) != 0 || ::mkfifo((dir_ / "ep2").c_str(), 0600) != 0) return;
        // The host's ends, never blocking the test.
        in_ = ::open((dir_ / "ep1").c_str(), O_RDWR | O_NONBLOCK);
        out_ = ::open((dir_ / "ep2").c_str(), O_RDWR | O_NONBLOCK);
        // The smallest pipe (a page), so that a host that never reads fills it in a moment.
        in_capacity_ = in_ >= 0 ? ::fcntl(in_, F_SETPIPE_SZ, 4096) : -1;
        ready_ = in_capacity_ > 0 && out_ >= 0;
    }
    ~FakeFunctionFs() {
        for (const int fd : {in_, out_, slave_, master_}) {
            if (fd >= 0) ::close(fd);
        }
        if (!dir_.empty()) {
            std::error_code ignored;
            fs::remove_all(dir_, ignored);
        }
    }
    FakeFunctionFs(const FakeFunctionFs&) = delete;
    FakeFunctionFs& operator=(const FakeFunctionFs&) = delete;

    [[nodiscard]] bool ready() const { return ready_; }
    [[nodiscard]] std::string dir() const { return dir_.string(); }

    // The host configured the device: FunctionFS's ENABLE event on ep0.
    void enable() const {
        usb_functionfs_event event{};
        event.type = FUNCTIONFS_ENABLE;
        ASSERT_EQ(::write(master_, &event, sizeof event), static_cast<ssize_t>(sizeof event));
    }
    // A host that sends: one full-speed packet of an output report on the OUT endpoint.
    [[nodiscard]] bool send_packet() const {
        std::array<uint8_t, 64> packet{};
        packet[0] = 0x0A;  // an output report id; what it says does not matter here
        return ::write(out_, packet.data(), packet.size()) > 0;
    }
    // The IN endpoint holds as much as it takes: the next input report finds no room.
    [[nodiscard]] bool in_full() const {
        int held = 0;
        return ::ioctl(in_, FIONREAD, &held) == 0 && held > in_capacity_ - 64;
    }
    // A host that reads: what the IN endpoint holds.
    void read_in() const {
        std::array<uint8_t, 4096> sink{};
        while (::read(in_, sink.data(), sink.size()) > 0) {
        }
    }

private:
    fs::path dir_;
    int master_ = -1, slave_ = -1, in_ = -1, out_ = -1;
    int in_capacity_ = -1;
    bool ready_ = false;
};

peripheral::PeripheralOptions usb_device_options() {
    peripheral::PeripheralOptions options;
    options.profile = "iforce2";
    options.runtime.realtime_priority = false;
    options.runtime.lock_memory = false;
    options.host_watchdog = false;  // as `feel device --usb`: the bus says when the host goes
    return options;
}

template <typename Condition>
bool wait_until(Condition condition, std::chrono::milliseconds limit) {
    const auto until = std::chrono::steady_clock::now() + limit;
    while (!condition()) {
        if (std::chrono::steady_clock::now() >= until) return false;
        std::this_thread::sleep_for(5ms);
    }
    return true;
}

// Serves a host that never reads its IN endpoint and otherwise does what `host_step` says
// (called every millisecond or so while the device serves and while it stops) until that
// endpoint is full, then stops the server. A stop() still blocked after kStopBound is
// released (the test feeds both endpoints until it returns) and reported as a failure, so
// the test ends either way.
template <typename HostStep>
void expect_bounded_stop(HostStep host_step) {
    FakeFunctionFs ffs;
    if (!ffs.ready()) GTEST_SKIP() << "no pseudo-terminal or FIFO for the FunctionFS stand-in in /tmp";
    peripheral::Peripheral device(usb_device_options());
    FunctionFsServer server(device, ffs.dir());
    ffs.enable();
    ASSERT_TRUE(wait_until([&] { return server.host_configured() && device.host_attached(); }, 10s))
        << "the ENABLE event on ep0 did not make the server attach a host";
    // Serve until the device's reports filled the IN endpoint.
    std::atomic<bool> host_stops{false};
    std::thread host([&] {
        while (!host_stops.load()) {
            host_step(ffs);
            std::this_thread::sleep_for(1ms);
        }
    });
    const bool served = wait_until([&] { return ffs.in_full(); }, 10s);

    const auto t0 = std::chrono::steady_clock::now();
    std::future<void> stopped = std::async(std::launch::async, [&] { server.stop(); });
    const bool in_time = stopped.wait_for(kStopBound) == std::future_status::ready;
    const auto took = std::chrono::steady_clock::now() - t0;
    while (stopped.wait_for(10ms) != std::future_status::ready) {
        (void)ffs.send_packet();  // release a submission that waits for the host
        ffs.read_in();
    }
    host_stops = true;
    host.join();
    device.stop();

    EXPECT_TRUE(served) << "the device's input reports did not fill the IN endpoint ("
                        << server.stats().input_reports << " written)";
    EXPECT_TRUE(in_time) << "stop() took "
                         << std::chrono::duration_cast<std::chrono::milliseconds>(took).count()
                         << " ms and returned only once the host took I/O again; the bound is "
                         << std::chrono::duration_cast<std::chrono::milliseconds>(kStopBound).count() << " ms";
}

TEST(FunctionFsServerStop, ReturnsWhileASilentHostNeverReads) {
    expect_bounded_stop([](const FakeFunctionFs&) {});  // nothing on OUT
}

TEST(FunctionFsServerStop, ReturnsWhileAHostFloodsAndNeverReads) {
    // The OUT endpoint kept full.
    expect_bounded_stop([](const FakeFunctionFs& ffs) {
        for (int i = 0; i < 16 && ffs.send_packet(); ++i) {
        }
    });
}

}  // namespace
}  // namespace feel::usb
