// ConfigfsGadget's refusals, on a directory that is not configfs: each names what is missing.
// (The set-up itself is tested against the kernel: tests/linux.)
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "feel/usb/usb_device.hpp"

namespace feel::usb {
namespace {

namespace fs = std::filesystem;

std::string message_of(const GadgetOptions& options) {
    try {
        ConfigfsGadget gadget(options);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

TEST(ConfigfsGadget, SaysWhenConfigfsOrLibcompositeIsMissing) {
    const fs::path root = fs::temp_directory_path() / ("feel-usb-test-" + std::to_string(::getpid()));
    fs::create_directories(root);
    GadgetOptions options;
    options.configfs_root = root.string();
    const std::string why = message_of(options);
    EXPECT_NE(why.find("usb_gadget is not there"), std::string::npos) << why;
    EXPECT_NE(why.find("modprobe libcomposite"), std::string::npos) << why;
    fs::remove_all(root);
}

TEST(ConfigfsGadget, RefusesToTakeOverAGadgetThatExists) {
    const fs::path root = fs::temp_directory_path() / ("feel-usb-test2-" + std::to_string(::getpid()));
    fs::create_directories(root / "usb_gadget" / "feel");
    GadgetOptions options;
    options.configfs_root = root.string();
    const std::string why = message_of(options);
    EXPECT_NE(why.find("already exists"), std::string::npos) << why;
    EXPECT_TRUE(fs::exists(root / "usb_gadget" / "feel"));  // left as it was
    fs::remove_all(root);
}

TEST(ConfigfsGadget, ListsControllersSorted) {
    const fs::path dir = fs::temp_directory_path() / ("feel-udc-test-" + std::to_string(::getpid()));
    fs::create_directories(dir / "b.usb");
    fs::create_directories(dir / "a.usb");
    EXPECT_EQ(ConfigfsGadget::controllers(dir.string()), (std::vector<std::string>{"a.usb", "b.usb"}));
    EXPECT_TRUE(ConfigfsGadget::controllers((dir / "none").string()).empty());
    fs::remove_all(dir);
}

}  // namespace
}  // namespace feel::usb
