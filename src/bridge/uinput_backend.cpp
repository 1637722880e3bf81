#include "uinput_backend.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <linux/uinput.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace feel::bridge {
namespace {

std::string errno_text(int e) { return std::strerror(e); }

void must(int result, const char* what) {
    if (result < 0) throw std::runtime_error(std::string("uinput: ") + what + " failed: " + errno_text(errno));
}

// /sys/devices/virtual/input/<sysname>/eventN -> /dev/input/eventN.
std::string event_node_of(const std::string& sysname) {
    const std::string dir = "/sys/devices/virtual/input/" + sysname;
    DIR* d = opendir(dir.c_str());
    if (d == nullptr) return {};
    std::string node;
    while (dirent* entry = readdir(d)) {
        if (std::strncmp(entry->d_name, "event", 5) == 0) node = std::string("/dev/input/") + entry->d_name;
    }
    closedir(d);
    return node;
}

}  // namespace

UinputDevice::UinputDevice(const UinputSpec& spec, const std::string& path) {
    fd_ = ::open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0) {
        const int e = errno;
        if (e == ENOENT || e == ENODEV || e == ENXIO) {
            throw std::runtime_error(path + " is missing (" + errno_text(e) +
                                     "): load the uinput module (sudo modprobe uinput)");
        }
        if (e == EACCES || e == EPERM) {
            throw std::runtime_error("no permission to open " + path +
                                     ": run as root, or let your user create input devices with a udev rule "
                                     "(docs/real-devices.md, \"feel bridge\")");
        }
        throw std::runtime_error("cannot open " + path + ": " + errno_text(e));
    }
    try {
        if (spec.max_effects < 1 || spec.max_effects > FF_MAX_EFFECTS) {
            throw std::invalid_argument("uinput: max_effects = " + std::to_string(spec.max_effects) +
                                        " is out of range (allowed 1..96)");
        }
        must(ioctl(fd_, UI_SET_EVBIT, EV_SYN), "UI_SET_EVBIT EV_SYN");
        if (!spec.buttons.empty()) must(ioctl(fd_, UI_SET_EVBIT, EV_KEY), "UI_SET_EVBIT EV_KEY");
        for (uint16_t code : spec.buttons) must(ioctl(fd_, UI_SET_KEYBIT, code), "UI_SET_KEYBIT");
        if (!spec.axes.empty()) must(ioctl(fd_, UI_SET_EVBIT, EV_ABS), "UI_SET_EVBIT EV_ABS");
        for (uint16_t code : spec.axes) {
            must(ioctl(fd_, UI_SET_ABSBIT, code), "UI_SET_ABSBIT");
            uinput_abs_setup abs{};
            abs.code = code;
            abs.absinfo.minimum = -10000;
            abs.absinfo.maximum = 10000;
            must(ioctl(fd_, UI_ABS_SETUP, &abs), "UI_ABS_SETUP");
        }
        if (!spec.ff_bits.empty()) must(ioctl(fd_, UI_SET_EVBIT, EV_FF), "UI_SET_EVBIT EV_FF");
        for (uint16_t code : spec.ff_bits) must(ioctl(fd_, UI_SET_FFBIT, code), "UI_SET_FFBIT");
        uinput_setup setup{};
        setup.id.bustype = BUS_VIRTUAL;
        setup.id.vendor = spec.vendor_id;
        setup.id.product = spec.product_id;
        setup.id.version = 1;
        std::strncpy(setup.name, spec.name.c_str(), UINPUT_MAX_NAME_SIZE - 1);
        setup.ff_effects_max = spec.max_effects;
        must(ioctl(fd_, UI_DEV_SETUP, &setup), "UI_DEV_SETUP");
        must(ioctl(fd_, UI_DEV_CREATE), "UI_DEV_CREATE");
        char sysname[64] = {};
        if (ioctl(fd_, UI_GET_SYSNAME(sizeof sysname), sysname) >= 0) {
            // The event node appears with the device; give udev-less systems a moment.
            for (int i = 0; i < 50 && event_node_.empty(); ++i) {
                event_node_ = event_node_of(sysname);
                if (event_node_.empty()) usleep(10'000);
            }
        }
    } catch (...) {
        ::close(fd_);
        throw;
    }
}

UinputDevice::~UinputDevice() {
    if (fd_ >= 0) {
        ioctl(fd_, UI_DEV_DESTROY);
        ::close(fd_);
    }
}

std::vector<UinputRequest> UinputDevice::wait(int timeout_ms) {
    std::vector<UinputRequest> out;
    pollfd p{fd_, POLLIN, 0};
    const int ready = poll(&p, 1, timeout_ms);
    if (ready < 0 && errno != EINTR) throw std::runtime_error("uinput: poll failed: " + errno_text(errno));
    if (ready <= 0) return out;
    input_event events[64];
    for (;;) {
        const ssize_t n = ::read(fd_, events, sizeof events);
        if (n < 0) {
            if (errno == EAGAIN || errno == EINTR) break;
            throw std::runtime_error("uinput: read failed: " + errno_text(errno));
        }
        const auto count = static_cast<std::size_t>(n) / sizeof(input_event);
        for (std::size_t i = 0; i < count; ++i) {
            const input_event& ev = events[i];
            UinputRequest r;
            if (ev.type == EV_UINPUT && (ev.code == UI_FF_UPLOAD || ev.code == UI_FF_ERASE)) {
                r.kind = ev.code == UI_FF_UPLOAD ? UinputRequest::Kind::upload : UinputRequest::Kind::erase;
                r.request_id = static_cast<uint32_t>(ev.value);
            } else if (ev.type == EV_FF && ev.code == FF_GAIN) {
                r.kind = UinputRequest::Kind::gain;
                r.value = ev.value;
            } else if (ev.type == EV_FF && ev.code == FF_AUTOCENTER) {
                r.kind = UinputRequest::Kind::autocenter;
                r.value = ev.value;
            } else if (ev.type == EV_FF) {
                r.kind = UinputRequest::Kind::play;
                r.code = ev.code;
                r.value = ev.value;
            } else {
                continue;  // LEDs, sounds: not ours
            }
            out.push_back(r);
        }
        if (count < sizeof events / sizeof events[0]) break;
    }
    return out;
}

std::optional<ff_effect> UinputDevice::begin_upload(uint32_t request_id) {
    uinput_ff_upload up{};
    up.request_id = request_id;
    if (ioctl(fd_, UI_BEGIN_FF_UPLOAD, &up) < 0) return std::nullopt;
    return up.effect;
}

void UinputDevice::end_upload(uint32_t request_id, const ff_effect& effect, int result) {
    uinput_ff_upload up{};
    up.request_id = request_id;
    up.retval = result;
    up.effect = effect;
    ioctl(fd_, UI_END_FF_UPLOAD, &up);
}

std::optional<int16_t> UinputDevice::begin_erase(uint32_t request_id) {
    uinput_ff_erase er{};
    er.request_id = request_id;
    if (ioctl(fd_, UI_BEGIN_FF_ERASE, &er) < 0) return std::nullopt;
    return static_cast<int16_t>(er.effect_id);
}

void UinputDevice::end_erase(uint32_t request_id, int16_t id, int result) {
    uinput_ff_erase er{};
    er.request_id = request_id;
    er.retval = result;
    er.effect_id = static_cast<uint32_t>(id);
    ioctl(fd_, UI_END_FF_ERASE, &er);
}

void UinputDevice::emit(uint16_t type, uint16_t code, int32_t value) {
    input_event ev{};
    ev.type = type;
    ev.code = code;
    ev.value = value;
    pending_.push_back(ev);
}

void UinputDevice::sync() {
    if (pending_.empty()) return;
    emit(EV_SYN, SYN_REPORT, 0);
    // The kernel stamps the time; a full buffer drops a state it will resend anyway.
    [[maybe_unused]] const ssize_t n =
        ::write(fd_, pending_.data(), pending_.size() * sizeof(input_event));
    pending_.clear();
}

}  // namespace feel::bridge
