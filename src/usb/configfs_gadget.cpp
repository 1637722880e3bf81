// ConfigfsGadget: a USB gadget made of one FunctionFS function, set up through configfs
// (Documentation/usb/gadget_configfs.rst in the Linux sources), the way a shell does it:
//
//   G=/sys/kernel/config/usb_gadget/feel
//   mkdir $G; echo 0x1209 > $G/idVendor; echo 0x0001 > $G/idProduct; ...
//   mkdir $G/strings/0x409; echo feel > $G/strings/0x409/manufacturer; ...
//   mkdir $G/configs/c.1; mkdir $G/functions/ffs.feel; ln -s $G/functions/ffs.feel $G/configs/c.1/
//   mount -t functionfs feel /run/feel/ffs-feel     (then the server writes ep0's descriptors)
//   echo dummy_udc.0 > $G/UDC                        (bind)
//
// and undoes it in reverse order. Every step that fails says which file and why; what was
// made before it is removed again.
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "feel/usb/usb_device.hpp"

namespace feel::usb {
namespace fs = std::filesystem;

namespace {

std::string hex4(uint16_t v) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%04x", v);
    return buf;
}

std::string errno_text() { return std::strerror(errno); }

}  // namespace

struct ConfigfsGadget::Impl {
    GadgetOptions options;
    fs::path gadget;
    std::string ffs_dir;
    std::string udc;
    // What exists, for undoing exactly that (in reverse order).
    std::vector<fs::path> made_dirs;
    fs::path link;
    bool mounted = false;
    bool bound = false;

    void write_attr(const fs::path& file, const std::string& value) const {
        FILE* f = std::fopen(file.c_str(), "w");
        if (f == nullptr) throw std::runtime_error("cannot open " + file.string() + ": " + errno_text());
        const bool wrote = std::fputs(value.c_str(), f) >= 0;
        const int saved = errno;
        const bool closed = std::fclose(f) == 0;  // configfs reports a refused value here
        if (!wrote || !closed) {
            errno = wrote ? errno : saved;
            throw std::runtime_error("cannot write \"" + value + "\" to " + file.string() + ": " + errno_text());
        }
    }
    void make_dir(const fs::path& dir) {
        if (::mkdir(dir.c_str(), 0755) != 0) {
            throw std::runtime_error("cannot create " + dir.string() + ": " + errno_text());
        }
        made_dirs.push_back(dir);
    }

    void create() {
        const fs::path root = fs::path(options.configfs_root) / "usb_gadget";
        std::error_code ec;
        if (!fs::is_directory(root, ec)) {
            throw std::runtime_error(root.string() +
                                     " is not there: mount configfs (mount -t configfs none " +
                                     options.configfs_root + ") and load libcomposite (modprobe libcomposite)");
        }
        if (options.name.empty() || options.name.find('/') != std::string::npos) {
            throw std::invalid_argument("the gadget name \"" + options.name + "\" is not a directory name");
        }
        gadget = root / options.name;
        if (fs::exists(gadget, ec)) {
            throw std::runtime_error("a gadget named \"" + options.name + "\" already exists (" + gadget.string() +
                                     "): another feel device runs, or one was killed; remove it first");
        }
        make_dir(gadget);
        write_attr(gadget / "idVendor", hex4(options.vendor_id));
        write_attr(gadget / "idProduct", hex4(options.product_id));
        write_attr(gadget / "bcdDevice", hex4(options.device_release_bcd));
        write_attr(gadget / "bcdUSB", "0x0200");
        make_dir(gadget / "strings" / "0x409");
        write_attr(gadget / "strings" / "0x409" / "manufacturer", options.manufacturer);
        write_attr(gadget / "strings" / "0x409" / "product", options.product);
        write_attr(gadget / "strings" / "0x409" / "serialnumber", options.serial);
        make_dir(gadget / "configs" / "c.1");
        make_dir(gadget / "configs" / "c.1" / "strings" / "0x409");
        write_attr(gadget / "configs" / "c.1" / "strings" / "0x409" / "configuration", "force feedback");
        write_attr(gadget / "configs" / "c.1" / "MaxPower", "100");
        const fs::path function = gadget / "functions" / ("ffs." + options.name);
        if (::mkdir(function.c_str(), 0755) != 0) {
            throw std::runtime_error("cannot create " + function.string() + ": " + errno_text() +
                                     (errno == ENOENT || errno == ENODEV
                                          ? " (load FunctionFS: modprobe usb_f_fs)"
                                          : ""));
        }
        made_dirs.push_back(function);
        link = gadget / "configs" / "c.1" / ("ffs." + options.name);
        if (::symlink(function.c_str(), link.c_str()) != 0) {
            const std::string why = errno_text();
            link.clear();
            throw std::runtime_error("cannot link the function into the configuration: " + why);
        }
        ffs_dir = options.mount_dir.empty() ? "/run/feel/ffs-" + options.name : options.mount_dir;
        fs::create_directories(ffs_dir, ec);
        if (ec) throw std::runtime_error("cannot create " + ffs_dir + ": " + ec.message());
        if (::mount(options.name.c_str(), ffs_dir.c_str(), "functionfs", 0, nullptr) != 0) {
            throw std::runtime_error("cannot mount FunctionFS instance \"" + options.name + "\" on " + ffs_dir +
                                     ": " + errno_text());
        }
        mounted = true;
    }

    void teardown() noexcept {
        unbind();
        if (mounted && ::umount(ffs_dir.c_str()) == 0) mounted = false;
        if (!link.empty()) {
            ::unlink(link.c_str());
            link.clear();
        }
        // configfs removes attribute files with their directory: rmdir in reverse order.
        for (auto it = made_dirs.rbegin(); it != made_dirs.rend(); ++it) ::rmdir(it->c_str());
        made_dirs.clear();
    }

    void unbind() noexcept {
        if (!bound) return;
        FILE* f = std::fopen((gadget / "UDC").c_str(), "w");
        if (f != nullptr) {
            std::fputs("\n", f);
            std::fclose(f);
        }
        bound = false;
    }
};

ConfigfsGadget::ConfigfsGadget(const GadgetOptions& options) : impl_(std::make_unique<Impl>()) {
    impl_->options = options;
    try {
        impl_->create();
    } catch (...) {
        impl_->teardown();
        throw;
    }
}

ConfigfsGadget::~ConfigfsGadget() { impl_->teardown(); }

const std::string& ConfigfsGadget::ffs_dir() const noexcept { return impl_->ffs_dir; }
const std::string& ConfigfsGadget::udc() const noexcept { return impl_->udc; }

std::vector<std::string> ConfigfsGadget::controllers(const std::string& udc_class_dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(udc_class_dir, ec), end; !ec && it != end; it.increment(ec)) {
        names.push_back(it->path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

void ConfigfsGadget::bind() {
    const std::vector<std::string> udcs = controllers(impl_->options.udc_class_dir);
    std::string list;
    for (const std::string& n : udcs) list += (list.empty() ? "" : ", ") + n;
    if (udcs.empty()) {
        throw std::runtime_error("no USB device controller in " + impl_->options.udc_class_dir +
                                 ": load one (dwc2 on a Raspberry Pi, dummy_hcd to test on one machine)");
    }
    std::string udc = impl_->options.udc.empty() ? udcs.front() : impl_->options.udc;
    if (std::find(udcs.begin(), udcs.end(), udc) == udcs.end()) {
        throw std::runtime_error("--udc \"" + udc + "\" is not a USB device controller of this machine (there are: " +
                                 list + ")");
    }
    impl_->write_attr(impl_->gadget / "UDC", udc);
    impl_->udc = udc;
    impl_->bound = true;
}

void ConfigfsGadget::unbind() noexcept { impl_->unbind(); }

}  // namespace feel::usb
