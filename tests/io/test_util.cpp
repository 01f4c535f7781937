#include "test_util.h"

#include <cstring>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

namespace mobb::test {

namespace fs = std::filesystem;

TempDir::TempDir() {
    std::string pattern = (fs::temp_directory_path() / "mobb-io-test-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::string TempDir::write(const std::string& name, const std::string& bytes) const {
    const fs::path file = path_ / name;
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + file.string());
    return file.string();
}

std::string mocap_dir() {
    const std::string dir = io::data_dir();
    std::error_code ec;
    if (dir.empty() || !fs::is_directory(fs::path(dir) / "cmu", ec) || !fs::is_directory(fs::path(dir) / "gltf", ec))
        return {};
    return dir;
}

bool data_required() {
    const char* v = std::getenv("MOBB_REQUIRE_DATA");
    return v != nullptr && std::string(v) == "1";
}

std::string missing_data_reason() {
    return "motion-capture data not found (set MOBB_DATA to the folder holding cmu/ and gltf/, or run "
           "next to ../shared/mocap); MOBB_REQUIRE_DATA=1 turns this skip into a failure";
}

void DataTest::SetUp() {
    dir_ = mocap_dir();
    if (!dir_.empty()) return;
    if (data_required()) FAIL() << missing_data_reason();
    GTEST_SKIP() << missing_data_reason();
}

std::string load_error(const std::function<void()>& f) {
    try {
        f();
    } catch (const io::LoadError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected LoadError, got another exception: " << e.what();
        return {};
    }
    ADD_FAILURE() << "expected LoadError, nothing was thrown";
    return {};
}

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const auto n = std::uint32_t(std::uint8_t(bytes[i])) << 16 | std::uint32_t(std::uint8_t(bytes[i + 1])) << 8 |
                       std::uint32_t(std::uint8_t(bytes[i + 2]));
        for (int k = 3; k >= 0; --k) out += table[(n >> (6 * k)) & 63];
    }
    if (i < bytes.size()) {
        std::uint32_t n = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) n |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        out += table[(n >> 18) & 63];
        out += table[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

std::string floats(const std::vector<float>& values) {
    std::string out(values.size() * 4, '\0');
    std::memcpy(out.data(), values.data(), out.size());  // x86 and ARM hosts are little-endian, like glTF
    return out;
}

namespace {
void put_u32(std::string& out, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) out += char((v >> (8 * k)) & 0xff);
}
}  // namespace

std::string make_glb(const std::string& json, const std::string& bin) {
    std::string j = json;
    while (j.size() % 4) j += ' ';
    std::string b = bin;
    while (b.size() % 4) b += '\0';
    std::string out = "glTF";
    put_u32(out, 2);
    put_u32(out, std::uint32_t(12 + 8 + j.size() + (b.empty() ? 0 : 8 + b.size())));
    put_u32(out, std::uint32_t(j.size()));
    put_u32(out, 0x4E4F534A);  // JSON
    out += j;
    if (!b.empty()) {
        put_u32(out, std::uint32_t(b.size()));
        put_u32(out, 0x004E4942);  // BIN
        out += b;
    }
    return out;
}

}  // namespace mobb::test
