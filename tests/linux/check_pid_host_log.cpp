// check_pid_host_log: did feel's USB device receive what the host API over hidraw asked
// for? (tests/linux/pid_host_probe.cpp in the VM, `make test-linux`.)
//
//   feel_check_pid_host_log --probe pid-host.txt --device-log device.log
//
// The probe's "pid expect KIND REPORT TOKENS..." lines are matched in order against the
// device log's lines ("<time> KIND REPORT field=value ..."): each must find, after the
// previous match of the same KIND, a line of that kind and report that carries every token.
// Order is kept per pipe: feature reports (set_feature, ep0) and output reports (the
// interrupt OUT endpoint) travel on different pipes, so one may overtake the other. The probe
// must also say that the device offered PID's eleven effect types plus Custom Force (feel's
// gadget declares Set Custom Force, Custom Force Data and Download Force Sample, so PidDevice
// plays custom forces natively: twelve usable types) and that it played the eleven without
// an error. Prints one line per check and "pid-host: N passed, M failed".
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> lines_of(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

int passed = 0, failed = 0;
void check(bool ok, const std::string& what) {
    std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
    (ok ? passed : failed) += 1;
}

}  // namespace

int main(int argc, char** argv) {
    std::string probe_path, log_path;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--probe") probe_path = argv[i + 1];
        else if (flag == "--device-log") log_path = argv[i + 1];
    }
    if (probe_path.empty() || log_path.empty()) {
        std::fprintf(stderr, "usage: feel_check_pid_host_log --probe FILE --device-log FILE\n");
        return 2;
    }
    const std::vector<std::string> probe = lines_of(probe_path);
    const std::vector<std::string> log = lines_of(log_path);
    bool saw_caps = false, saw_done = false;
    std::map<std::string, std::size_t> at;  // per kind: the device log line after its last match
    int expectations = 0;
    for (const std::string& line : probe) {
        if (line.rfind("pid error", 0) == 0) check(false, line);
        if (line.rfind("pid caps", 0) == 0) {
            saw_caps = true;
            check(line.find(" feel_device=1") != std::string::npos && line.find(" types=12 ") != std::string::npos,
                  "the host read PID's eleven effect types and Custom Force from the gadget's descriptor: " + line);
        }
        if (line.rfind("pid done", 0) == 0) {
            saw_done = true;
            check(line.find(" effects=11 errors=0") != std::string::npos, "the host played every type: " + line);
        }
        if (line.rfind("pid expect ", 0) != 0) continue;
        ++expectations;
        const std::vector<std::string> want = words(line.substr(11));
        if (want.size() < 2) {
            check(false, "malformed expectation: " + line);
            continue;
        }
        bool found = false;
        std::size_t& from = at[want[0]];
        for (std::size_t i = from; i < log.size() && !found; ++i) {
            const std::vector<std::string> got = words(log[i]);
            if (got.size() < 3 || got[1] != want[0] || got[2] != want[1]) continue;
            bool all = true;
            for (std::size_t k = 2; k < want.size() && all; ++k) {
                bool has = false;
                for (std::size_t g = 3; g < got.size() && !has; ++g) has = got[g] == want[k];
                all = has;
            }
            if (all) {
                found = true;
                from = i + 1;
            }
        }
        check(found, "the device received " + line.substr(11));
    }
    check(saw_caps && saw_done, "the probe ran to its end");
    check(expectations >= 11 * 5, "the probe asked for every type's reports (" + std::to_string(expectations) + ")");
    std::printf("pid-host: %d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
