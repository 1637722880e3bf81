// The byte-stream transports over Unix domain sockets and TCP loopback: framing, partial
// frames, hostile bytes, timeouts, closes from either side, and the listener's socket file.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include "feel/transport/transport.hpp"
#include "frame_of.hpp"

namespace feel::transport {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

std::vector<uint8_t> pattern(std::size_t size, uint8_t seed) {
    std::vector<uint8_t> bytes(size);
    for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<uint8_t>(seed + i * 7);
    return bytes;
}

// The wire form, written out by hand from the documented layout (not by the library).
std::vector<uint8_t> wire(uint8_t kind, uint16_t length, const std::vector<uint8_t>& payload) {
    std::vector<uint8_t> bytes = {kind, static_cast<uint8_t>(length & 0xFF), static_cast<uint8_t>(length >> 8)};
    bytes.insert(bytes.end(), payload.begin(), payload.end());
    return bytes;
}

TransportError::Kind stream_receive_error(Connection& c, std::chrono::milliseconds timeout = 2000ms) {
    try {
        const auto f = c.receive(timeout);
        ADD_FAILURE() << (f ? "a frame came instead of an error" : "timed out instead of an error");
    } catch (const TransportError& e) {
        return e.kind();
    }
    return TransportError::Kind::timeout;
}

// A scratch directory for socket files, removed afterwards.
class TempDir {
public:
    TempDir() {
        char name[] = "/tmp/feel-transport-test-XXXXXX";
        path_ = ::mkdtemp(name);
    }
    ~TempDir() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    [[nodiscard]] std::string file(const std::string& name) const { return path_ + "/" + name; }

private:
    std::string path_;
};

// A plain POSIX client socket, to write bytes the library would never write.
class RawClient {
public:
    explicit RawClient(const Address& address) {
        if (address.kind == Address::Kind::unix_socket) {
            fd_ = ::socket(AF_UNIX, SOCK_STREAM, 0);
            sockaddr_un a{};
            a.sun_family = AF_UNIX;
            std::strncpy(a.sun_path, address.path.c_str(), sizeof a.sun_path - 1);
            connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
        } else {
            fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
            const int on = 1;
            ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
            sockaddr_in a{};
            a.sin_family = AF_INET;
            a.sin_port = htons(address.port);
            ::inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
            connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
        }
    }
    ~RawClient() { ::close(fd_); }
    RawClient(const RawClient&) = delete;
    RawClient& operator=(const RawClient&) = delete;

    [[nodiscard]] bool connected() const { return connected_; }
    void write(const std::vector<uint8_t>& bytes) const {
        std::size_t sent = 0;
        while (sent < bytes.size()) {
            const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
            ASSERT_GT(n, 0);
            sent += static_cast<std::size_t>(n);
        }
    }
    // True when the other side closed: a read returns end of stream (or a reset) in time.
    [[nodiscard]] bool sees_close(std::chrono::milliseconds timeout) const {
        timeval tv{};
        tv.tv_sec = static_cast<time_t>(timeout.count() / 1000);
        tv.tv_usec = static_cast<suseconds_t>((timeout.count() % 1000) * 1000);
        ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
        uint8_t byte = 0;
        for (;;) {
            const ssize_t n = ::recv(fd_, &byte, 1, 0);
            if (n == 0) return true;
            if (n < 0) return errno == ECONNRESET || errno == EPIPE;
        }
    }
    void close() {
        ::close(fd_);
        fd_ = -1;
    }

private:
    int fd_ = -1;
    bool connected_ = false;
};

enum class Kind { unix_socket, tcp };

class StreamTransport : public ::testing::TestWithParam<Kind> {
protected:
    void SetUp() override {
        Address where;
        if (GetParam() == Kind::unix_socket) {
            where.kind = Address::Kind::unix_socket;
            where.path = dir_.file("device.sock");
        } else {
            where = Address::parse_listen("tcp:127.0.0.1:0");
        }
        listener_ = listen(where);
        address_ = listener_->address();
    }

    // A connected host end and the device end it reached.
    ConnectionPair connect_pair() {
        ConnectionPair pair;
        pair.host = connect(address_, 2000ms);
        pair.device = listener_->accept(2000ms);
        EXPECT_NE(pair.device, nullptr);
        return pair;
    }

    // The device end of a raw client's connection.
    std::unique_ptr<Connection> accept_raw(const RawClient& raw) {
        EXPECT_TRUE(raw.connected());
        auto device = listener_->accept(2000ms);
        EXPECT_NE(device, nullptr);
        return device;
    }

    TempDir dir_;
    std::unique_ptr<Listener> listener_;
    Address address_;
};

TEST_P(StreamTransport, ListensAtTheAddressItSays) {
    if (GetParam() == Kind::tcp) {
        EXPECT_EQ(address_.kind, Address::Kind::tcp);
        EXPECT_NE(address_.port, 0);  // port 0 asked for any free port; this is the one bound
    } else {
        EXPECT_EQ(address_.to_string(), "unix:" + dir_.file("device.sock"));
        struct stat info {};
        ASSERT_EQ(::lstat(address_.path.c_str(), &info), 0);
        EXPECT_TRUE(S_ISSOCK(info.st_mode));
    }
}

TEST_P(StreamTransport, RoundTripsFramesOfEverySizeBothWays) {
    ConnectionPair pair = connect_pair();
    EXPECT_EQ(pair.host->peer(), address_.to_string());
    EXPECT_EQ(pair.device->peer().rfind(GetParam() == Kind::tcp ? "tcp:127.0.0.1:" : "unix:", 0), 0u)
        << pair.device->peer();
    for (const std::size_t size : {std::size_t{0}, std::size_t{1}, kMaxFramePayload}) {
        const Frame out = frame_of(FrameKind::set_feature, pattern(size, static_cast<uint8_t>(size)));
        pair.host->send(out);
        const auto in = pair.device->receive(2000ms);
        ASSERT_TRUE(in.has_value());
        EXPECT_EQ(*in, out);
        const Frame reply = frame_of(FrameKind::feature_reply, pattern(size, 3));
        pair.device->send(reply);
        const auto back = pair.host->receive(2000ms);
        ASSERT_TRUE(back.has_value());
        EXPECT_EQ(*back, reply);
    }
    EXPECT_THROW(pair.host->send(frame_of(FrameKind::output_report, std::vector<uint8_t>(kMaxFramePayload + 1))),
                 std::invalid_argument);
}

TEST_P(StreamTransport, ABurstOfFramesArrivesInOrder) {
    ConnectionPair pair = connect_pair();
    constexpr int kFrames = 20'000;
    // Every kind but hello, which the device's end takes itself (it carries a token).
    constexpr int kKinds = kFrameKindCount - 1;
    std::thread sender([&] {
        for (int i = 0; i < kFrames; ++i) {
            std::vector<uint8_t> payload = pattern(static_cast<std::size_t>(i % 61), static_cast<uint8_t>(i));
            payload.insert(payload.begin(), {uint8_t(i & 0xFF), uint8_t((i >> 8) & 0xFF)});
            pair.host->send(frame_of(static_cast<FrameKind>(1 + i % kKinds), std::move(payload)));
        }
    });
    for (int i = 0; i < kFrames; ++i) {
        const auto f = pair.device->receive(5000ms);
        ASSERT_TRUE(f.has_value()) << "frame " << i;
        ASSERT_EQ(static_cast<int>(f->kind), 1 + i % kKinds);
        ASSERT_EQ(f->payload.size(), static_cast<std::size_t>(2 + i % 61));
        ASSERT_EQ(f->payload[0] | (f->payload[1] << 8), i & 0xFFFF);
        std::vector<uint8_t> rest(f->payload.begin() + 2, f->payload.end());
        ASSERT_EQ(rest, pattern(static_cast<std::size_t>(i % 61), static_cast<uint8_t>(i)));
    }
    sender.join();
}

TEST_P(StreamTransport, FramesWrittenOneByteAtATimeArriveWhole) {
    RawClient raw(address_);
    auto device = accept_raw(raw);
    const std::vector<uint8_t> first = pattern(300, 9);
    std::vector<uint8_t> bytes = wire(1, 300, first);
    const std::vector<uint8_t> second = wire(3, 2, {0x42, 0x43});
    bytes.insert(bytes.end(), second.begin(), second.end());
    const std::vector<uint8_t> empty = wire(6, 0, {});
    bytes.insert(bytes.end(), empty.begin(), empty.end());
    std::thread writer([&] {
        for (std::size_t i = 0; i < bytes.size(); ++i) {
            raw.write({bytes[i]});
            if (i < 8 || i % 50 == 0) std::this_thread::sleep_for(1ms);  // separate reads for sure
        }
    });
    const auto a = device->receive(5000ms);
    const auto b = device->receive(5000ms);
    const auto c = device->receive(5000ms);
    writer.join();
    ASSERT_TRUE(a && b && c);
    EXPECT_EQ(*a, frame_of(FrameKind::output_report, first));
    EXPECT_EQ(*b, frame_of(FrameKind::set_feature, {0x42, 0x43}));
    EXPECT_EQ(*c, frame_of(FrameKind::get_descriptor, {}));
}

TEST_P(StreamTransport, HostileBytesAreABadFrameAndCloseTheConnection) {
    struct Hostile {
        std::vector<uint8_t> bytes;
        const char* what;
    };
    const Hostile cases[] = {
        {wire(0, 1, {7}), "unknown kind 0"},
        {wire(10, 1, {7}), "unknown kind 10"},
        {wire(255, 0, {}), "unknown kind 255"},
        {wire(1, 4097, {}), "4097 bytes"},
        {wire(7, 65535, {}), "65535 bytes"},
    };
    for (const Hostile& h : cases) {
        RawClient raw(address_);
        auto device = accept_raw(raw);
        // A good frame first: it is delivered; the bad header after it is not a frame.
        std::vector<uint8_t> bytes = wire(2, 1, {5});
        bytes.insert(bytes.end(), h.bytes.begin(), h.bytes.end());
        raw.write(bytes);
        const auto good = device->receive(2000ms);
        ASSERT_TRUE(good.has_value());
        EXPECT_EQ(*good, frame_of(FrameKind::input_report, {5}));
        try {
            (void)device->receive(2000ms);
            ADD_FAILURE() << h.what << ": accepted";
        } catch (const TransportError& e) {
            EXPECT_EQ(e.kind(), TransportError::Kind::bad_frame) << h.what;
            EXPECT_NE(std::string(e.what()).find(h.what), std::string::npos) << e.what();
        }
        EXPECT_EQ(stream_receive_error(*device), TransportError::Kind::disconnected) << h.what;
        EXPECT_TRUE(raw.sees_close(2000ms)) << h.what << ": the device kept the connection open";
    }
}

TEST_P(StreamTransport, ReceiveTimesOutWithNothing) {
    ConnectionPair pair = connect_pair();
    const auto begin = std::chrono::steady_clock::now();
    EXPECT_FALSE(pair.device->receive(40ms).has_value());
    EXPECT_GE(std::chrono::steady_clock::now() - begin, 40ms);
    EXPECT_FALSE(pair.host->receive(0ms).has_value());
    // Half a frame is not a frame: still nothing, and the rest completes it.
    RawClient raw(address_);
    auto device = accept_raw(raw);
    raw.write({1, 3, 0, 0xAA});
    EXPECT_FALSE(device->receive(30ms).has_value());
    raw.write({0xBB, 0xCC});
    const auto f = device->receive(2000ms);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(*f, frame_of(FrameKind::output_report, {0xAA, 0xBB, 0xCC}));
}

TEST_P(StreamTransport, WaitingForEverIsAllowed) {
    ConnectionPair pair = connect_pair();
    std::thread sender([&] {
        std::this_thread::sleep_for(20ms);
        pair.host->send(frame_of(FrameKind::output_report, {9}));
    });
    const auto f = pair.device->receive(std::chrono::milliseconds::max());
    sender.join();
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->payload, std::vector<uint8_t>{9});
    auto second = connect(address_, std::chrono::milliseconds::max());
    EXPECT_NE(listener_->accept(std::chrono::milliseconds::max()), nullptr);
}

TEST_P(StreamTransport, PeerCloseIsDisconnectedAfterThePendingFrames) {
    ConnectionPair pair = connect_pair();
    for (uint8_t i = 0; i < 10; ++i) pair.host->send(frame_of(FrameKind::output_report, {i}));
    pair.host->close();
    for (uint8_t i = 0; i < 10; ++i) {
        const auto f = pair.device->receive(2000ms);
        ASSERT_TRUE(f.has_value());
        EXPECT_EQ(f->payload, std::vector<uint8_t>{i});
    }
    EXPECT_EQ(stream_receive_error(*pair.device), TransportError::Kind::disconnected);
    EXPECT_EQ(stream_receive_error(*pair.host), TransportError::Kind::disconnected);  // closed here
}

TEST_P(StreamTransport, APeerVanishingMidFrameIsDisconnected) {
    RawClient raw(address_);
    auto device = accept_raw(raw);
    raw.write({1, 10, 0, 1, 2, 3});
    raw.close();
    EXPECT_EQ(stream_receive_error(*device), TransportError::Kind::disconnected);
}

TEST_P(StreamTransport, SendingToAClosedPeerIsDisconnectedNotASignal) {
    ConnectionPair pair = connect_pair();
    pair.device.reset();  // the device end is gone
    bool disconnected = false;
    // The first sends may still fit in the socket's buffer; the peer's reset ends them.
    for (int i = 0; i < 1000 && !disconnected; ++i) {
        try {
            pair.host->send(frame_of(FrameKind::output_report, pattern(1000, 1)));
        } catch (const TransportError& e) {
            EXPECT_EQ(e.kind(), TransportError::Kind::disconnected);
            disconnected = true;
        }
        std::this_thread::sleep_for(1ms);
    }
    EXPECT_TRUE(disconnected);
    pair.host->close();
    EXPECT_THROW(pair.host->send(frame_of(FrameKind::output_report, {})), TransportError);
}

TEST_P(StreamTransport, CloseWakesABlockedReceiveAndABlockedAccept) {
    ConnectionPair pair = connect_pair();
    TransportError::Kind kind = TransportError::Kind::timeout;
    std::thread receiver([&] { kind = stream_receive_error(*pair.device, 10'000ms); });
    std::this_thread::sleep_for(20ms);
    const auto begin = std::chrono::steady_clock::now();
    pair.device->close();
    receiver.join();
    EXPECT_EQ(kind, TransportError::Kind::disconnected);
    EXPECT_LT(std::chrono::steady_clock::now() - begin, 5000ms);

    EXPECT_EQ(listener_->accept(20ms), nullptr);  // nobody came: nullptr in time
    bool accept_threw = false;
    std::thread acceptor([&] {
        try {
            (void)listener_->accept(10'000ms);
        } catch (const TransportError& e) {
            accept_threw = e.kind() == TransportError::Kind::disconnected;
        }
    });
    std::this_thread::sleep_for(20ms);
    listener_->close();
    acceptor.join();
    EXPECT_TRUE(accept_threw);
    EXPECT_THROW((void)connect(address_, 500ms), TransportError);  // no longer listening
}

TEST_P(StreamTransport, ConnectingToNothingIsRefused) {
    listener_->close();
    listener_.reset();
    try {
        (void)connect(address_, 1000ms);
        ADD_FAILURE() << "connected to nothing";
    } catch (const TransportError& e) {
        EXPECT_EQ(e.kind(), TransportError::Kind::refused) << e.what();
        EXPECT_NE(std::string(e.what()).find(address_.to_string()), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Transports, StreamTransport, ::testing::Values(Kind::unix_socket, Kind::tcp),
                         [](const ::testing::TestParamInfo<Kind>& param_info) { return param_info.param == Kind::tcp ? "tcp" : "unix"; });

// --- Unix socket files -------------------------------------------------------------------

Address unix_address(const std::string& path) {
    Address a;
    a.kind = Address::Kind::unix_socket;
    a.path = path;
    return a;
}

TEST(UnixListener, ClosingRemovesItsSocketFile) {
    TempDir dir;
    const std::string path = dir.file("sim.sock");
    auto listener = listen(unix_address(path));
    EXPECT_TRUE(fs::exists(path));
    listener->close();
    EXPECT_FALSE(fs::exists(path));
    listener.reset();
    // Destroying without close() removes it too.
    listener = listen(unix_address(path));
    listener.reset();
    EXPECT_FALSE(fs::exists(path));
}

TEST(UnixListener, TakesOverAStaleSocketAndRefusesALiveOne) {
    TempDir dir;
    const std::string path = dir.file("sim.sock");
    {
        // A device that crashed: its socket file is there, nobody listens.
        const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
        sockaddr_un a{};
        a.sun_family = AF_UNIX;
        std::strncpy(a.sun_path, path.c_str(), sizeof a.sun_path - 1);
        ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
        ::close(fd);
    }
    ASSERT_TRUE(fs::exists(path));
    auto listener = listen(unix_address(path));  // taken over
    auto host = connect(unix_address(path), 1000ms);
    auto device = listener->accept(1000ms);
    ASSERT_NE(device, nullptr);
    host->send(frame_of(FrameKind::get_descriptor, {}));
    EXPECT_TRUE(device->receive(1000ms).has_value());

    try {
        (void)listen(unix_address(path));
        ADD_FAILURE() << "two devices at one socket";
    } catch (const TransportError& e) {
        EXPECT_EQ(e.kind(), TransportError::Kind::refused);
        EXPECT_NE(std::string(e.what()).find("already listens"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::exists(path));  // the refused one did not remove the live device's file
}

TEST(UnixListener, RefusesAPathThatIsNotASocketOrCannotBe) {
    TempDir dir;
    const std::string file = dir.file("notes.txt");
    std::ofstream(file) << "keep me";
    try {
        (void)listen(unix_address(file));
        ADD_FAILURE() << "listened over a file";
    } catch (const TransportError& e) {
        EXPECT_EQ(e.kind(), TransportError::Kind::refused);
        EXPECT_NE(std::string(e.what()).find("not a socket"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::exists(file));
    EXPECT_THROW((void)listen(unix_address(dir.file("no/such/dir.sock"))), TransportError);
    EXPECT_THROW((void)listen(unix_address("/tmp/" + std::string(200, 'x'))), TransportError);
    EXPECT_THROW((void)connect(unix_address(dir.file("nobody.sock")), 500ms), TransportError);
}

TEST(Listen, SimAddressesNeedNoListenerAndCannotBeConnectedTo) {
    EXPECT_THROW((void)listen(Address::parse("sim:iforce2")), std::invalid_argument);
    EXPECT_THROW((void)connect(Address::parse("sim:iforce2"), 10ms), std::invalid_argument);
}

TEST(TcpListener, ATakenPortIsRefused) {
    auto first = listen(Address::parse_listen("tcp:127.0.0.1:0"));
    try {
        (void)listen(first->address());
        ADD_FAILURE() << "two listeners on one port";
    } catch (const TransportError& e) {
        EXPECT_EQ(e.kind(), TransportError::Kind::refused);
        EXPECT_NE(std::string(e.what()).find(first->address().to_string()), std::string::npos) << e.what();
    }
}


// --- a device's end never held by its peer (transport.hpp) ---------------------------------

TEST_P(StreamTransport, APartialFrameNotCompletedInTimeClosesTheConnection) {
    RawClient raw(address_);
    auto device = accept_raw(raw);
    raw.write({1, 40, 0, 0xAA, 0xBB});  // an output report of 40 bytes: 2 of them, then nothing
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(stream_receive_error(*device, 5000ms), TransportError::Kind::bad_frame);
    const auto waited = std::chrono::steady_clock::now() - start;
    EXPECT_GE(waited, kPartialFrameTimeout - 50ms);
    EXPECT_TRUE(raw.sees_close(2000ms));
}

TEST_P(StreamTransport, APartialFrameCompletedAfterAPauseOfTheReaderIsNotBlamedOnThePeer) {
    RawClient raw(address_);
    auto device = accept_raw(raw);
    raw.write({1, 4, 0, 1});
    EXPECT_FALSE(device->receive(20ms).has_value());  // the partial frame is buffered
    raw.write({2, 3, 4});                             // the rest comes at once ...
    std::this_thread::sleep_for(kPartialFrameTimeout + 100ms);  // ... but the reader pauses
    const auto f = device->receive(100ms);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->payload, (std::vector<uint8_t>{1, 2, 3, 4}));
}

TEST_P(StreamTransport, APeerThatNeverReadsIsDroppedAndSendsNeverBlock) {
    RawClient raw(address_);
    auto device = accept_raw(raw);
    const Frame big = frame_of(FrameKind::descriptor_reply, pattern(kMaxFramePayload, 3));
    bool dropped = false;
    std::string why;
    const auto start = std::chrono::steady_clock::now();
    auto slowest = std::chrono::steady_clock::duration::zero();
    for (int i = 0; i < 100'000 && !dropped; ++i) {
        const auto before = std::chrono::steady_clock::now();
        try {
            device->send(big);
        } catch (const TransportError& e) {
            dropped = true;
            why = e.what();
            EXPECT_EQ(e.kind(), TransportError::Kind::disconnected);
        }
        slowest = std::max(slowest, std::chrono::steady_clock::now() - before);
    }
    ASSERT_TRUE(dropped);
    EXPECT_NE(why.find("does not read"), std::string::npos) << why;
    EXPECT_LT(slowest, 100ms) << "a send waited for the peer";
    EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
    EXPECT_THROW(device->send(big), TransportError);
}

TEST_P(StreamTransport, APeerThatStopsTakingBytesIsDroppedAfterTheStallTime) {
    RawClient raw(address_);
    auto device = accept_raw(raw);
    // Small droppable frames until the socket is full: then they are dropped, not queued.
    const Frame state = frame_of(FrameKind::input_report, pattern(40, 9));
    int sent = 0;
    int dropped = 0;
    const auto start = std::chrono::steady_clock::now();
    bool closed = false;
    while (!closed && std::chrono::steady_clock::now() - start < 10s) {
        try {
            if (device->send_or_drop(state)) ++sent;
            else ++dropped;
        } catch (const TransportError& e) {
            closed = true;
            EXPECT_NE(std::string(e.what()).find("took none"), std::string::npos) << e.what();
        }
        std::this_thread::sleep_for(100us);
    }
    EXPECT_TRUE(closed);
    EXPECT_GT(sent, 0);
    EXPECT_GT(dropped, 0);
}

TEST_P(StreamTransport, AReadingPeerGetsEveryFrameSendOrDropKeeps) {
    auto pair = connect_pair();
    // A peer that reads as the frames come: nothing waits, so nothing is dropped.
    for (int i = 0; i < 500; ++i) {
        ASSERT_TRUE(pair.device->send_or_drop(frame_of(FrameKind::input_report, {static_cast<uint8_t>(i)}))) << i;
        const auto f = pair.host->receive(2000ms);
        ASSERT_TRUE(f.has_value());
        EXPECT_EQ(f->payload[0], static_cast<uint8_t>(i));
    }
}

// --- the shared secret -------------------------------------------------------------------------

class TokenTransport : public ::testing::TestWithParam<Kind> {
protected:
    void SetUp() override {
        Address where;
        if (GetParam() == Kind::unix_socket) {
            where.kind = Address::Kind::unix_socket;
            where.path = dir_.file("device.sock");
        } else {
            where = Address::parse_listen("tcp:127.0.0.1:0");
        }
        ListenOptions options;
        options.token = "s3cret-Token";
        listener_ = listen(where, options);
        address_ = listener_->address();
    }
    TempDir dir_;
    std::unique_ptr<Listener> listener_;
    Address address_;
};

TEST_P(TokenTransport, AHostWithTheTokenIsServedItsHelloNeverSeen) {
    Address with = address_;
    with.token = "s3cret-Token";
    auto host = connect(with, 2000ms);
    auto device = listener_->accept(2000ms);
    ASSERT_NE(device, nullptr);
    host->send(frame_of(FrameKind::get_descriptor, {}));
    const auto f = device->receive(2000ms);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->kind, FrameKind::get_descriptor);
}

TEST_P(TokenTransport, TheTokenMayComeFromTheEnvironment) {
    ::setenv(kTokenEnvironmentVariable, "s3cret-Token", 1);
    auto host = connect(address_, 2000ms);
    ::unsetenv(kTokenEnvironmentVariable);
    auto device = listener_->accept(2000ms);
    ASSERT_NE(device, nullptr);
    host->send(frame_of(FrameKind::get_descriptor, {}));
    const auto f = device->receive(2000ms);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->kind, FrameKind::get_descriptor);
}

TEST_P(TokenTransport, AWrongOrMissingTokenClosesTheConnection) {
    Address wrong = address_;
    wrong.token = "s3cret-Tokem";
    auto host = connect(wrong, 2000ms);
    auto device = listener_->accept(2000ms);
    ASSERT_NE(device, nullptr);
    host->send(frame_of(FrameKind::get_descriptor, {}));
    try {
        (void)device->receive(2000ms);
        ADD_FAILURE() << "a wrong token was accepted";
    } catch (const TransportError& e) {
        EXPECT_EQ(e.kind(), TransportError::Kind::bad_frame);
        EXPECT_NE(std::string(e.what()).find("wrong token"), std::string::npos) << e.what();
    }
    auto bare = connect(address_, 2000ms);
    auto device2 = listener_->accept(2000ms);
    ASSERT_NE(device2, nullptr);
    bare->send(frame_of(FrameKind::get_descriptor, {}));
    try {
        (void)device2->receive(2000ms);
        ADD_FAILURE() << "a host without a token was accepted";
    } catch (const TransportError& e) {
        EXPECT_EQ(e.kind(), TransportError::Kind::bad_frame);
        EXPECT_NE(std::string(e.what()).find("before presenting the device's token"), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Transports, TokenTransport, ::testing::Values(Kind::unix_socket, Kind::tcp),
                         [](const ::testing::TestParamInfo<Kind>& param_info) {
                             return param_info.param == Kind::tcp ? "tcp" : "unix";
                         });

TEST(TokenTransport, ADeviceWithoutATokenIgnoresAHello) {
    TempDir dir;
    Address where;
    where.kind = Address::Kind::unix_socket;
    where.path = dir.file("d.sock");
    auto listener = listen(where);
    ::setenv(kTokenEnvironmentVariable, "anything", 1);
    auto host = connect(where, 2000ms);
    ::unsetenv(kTokenEnvironmentVariable);
    auto device = listener->accept(2000ms);
    ASSERT_NE(device, nullptr);
    host->send(frame_of(FrameKind::get_descriptor, {}));
    const auto f = device->receive(2000ms);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->kind, FrameKind::get_descriptor);
}

// --- who may connect -------------------------------------------------------------------------

TEST(Listen, ABeyondLoopbackAddressNeedsAllowRemoteAndAToken) {
    const Address any = Address::parse_listen("tcp:0.0.0.0:0");
    try {
        (void)listen(any);
        ADD_FAILURE() << "listened beyond loopback without --allow-remote";
    } catch (const TransportError& e) {
        EXPECT_EQ(e.kind(), TransportError::Kind::refused);
        EXPECT_NE(std::string(e.what()).find("--allow-remote"), std::string::npos) << e.what();
    }
    ListenOptions remote;
    remote.allow_remote = true;
    try {
        (void)listen(any, remote);
        ADD_FAILURE() << "listened beyond loopback without a token";
    } catch (const TransportError& e) {
        EXPECT_NE(std::string(e.what()).find("token"), std::string::npos) << e.what();
    }
    remote.token = "abc";
    EXPECT_NO_THROW((void)listen(any, remote));
    // Loopback needs neither.
    EXPECT_NO_THROW((void)listen(Address::parse_listen("tcp:127.0.0.1:0")));
}

TEST(Listen, SocketFilesAreForTheUserAloneWhateverTheUmask) {
    TempDir dir;
    const mode_t old = ::umask(0);
    Address where;
    where.kind = Address::Kind::unix_socket;
    where.path = dir.file("open.sock");
    auto listener = listen(where);
    struct stat info {};
    ASSERT_EQ(::stat(where.path.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0600u);
    // With a group: 0660 and that group (the user's own, which a user may always give).
    ListenOptions grouped;
    grouped.group_id = static_cast<unsigned>(::getgid());
    Address second = where;
    second.path = dir.file("group.sock");
    ::umask(0077);
    auto group_listener = listen(second, grouped);
    ::umask(old);
    ASSERT_EQ(::stat(second.path.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0660u);
    EXPECT_EQ(info.st_gid, ::getgid());
}

TEST(Access, LoopbackIsJudgedByEveryAddressAHostStandsFor) {
    for (const char* host : {"127.0.0.1", "127.3.2.1", "::1", "::ffff:127.0.0.1", "localhost"})
        EXPECT_TRUE(is_loopback_host(host)) << host;
    for (const char* host : {"0.0.0.0", "::", "10.1.2.3", "192.168.0.7", "::ffff:10.0.0.1"})
        EXPECT_FALSE(is_loopback_host(host)) << host;
}

TEST(Access, TokensArePrintableAsciiWithoutSpaces) {
    EXPECT_EQ(check_token("abc-DEF_123.~"), "");
    EXPECT_NE(check_token("").find("empty"), std::string::npos);
    EXPECT_NE(check_token("a b").find("0x20"), std::string::npos);
    EXPECT_NE(check_token(std::string(kMaxTokenBytes + 1, 'x')).find("257 bytes"), std::string::npos);
}

TEST(Access, APrivateSocketDirIsUsedAndAnyOtherReplacedByAFreshOne) {
    TempDir dir;
    const std::string mine = dir.file("mine");
    PrivateDir got = private_socket_dir(mine);  // made, 0700
    EXPECT_EQ(got.path, mine);
    EXPECT_TRUE(got.warning.empty()) << got.warning;
    struct stat info {};
    ASSERT_EQ(::stat(mine.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0700u);

    // One already there and open to others: not used (someone may have used it already),
    // and not changed; a fresh one instead.
    const std::string open_dir = dir.file("open");
    ASSERT_EQ(::mkdir(open_dir.c_str(), 0700), 0);
    ASSERT_EQ(::chmod(open_dir.c_str(), 0777), 0);
    got = private_socket_dir(open_dir);
    EXPECT_NE(got.path, open_dir);
    EXPECT_NE(got.warning.find("0777"), std::string::npos) << got.warning;
    ASSERT_EQ(::lstat(got.path.c_str(), &info), 0);
    EXPECT_TRUE(S_ISDIR(info.st_mode));
    EXPECT_EQ(info.st_mode & 07777, 0700u);
    EXPECT_EQ(info.st_uid, ::getuid());
    fs::remove_all(got.path);
    ASSERT_EQ(::stat(open_dir.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0777u);

    // A symbolic link to a private directory is not used either.
    const std::string link = dir.file("link");
    ASSERT_EQ(::symlink(mine.c_str(), link.c_str()), 0);
    got = private_socket_dir(link);
    EXPECT_NE(got.path, link);
    EXPECT_NE(got.warning.find("symbolic link"), std::string::npos) << got.warning;
    fs::remove_all(got.path);
}

}  // namespace
}  // namespace feel::transport
