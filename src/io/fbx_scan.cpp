#include "fbx_scan.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

namespace mobb::io::fbx {
namespace {

using Edge = std::pair<std::int64_t, std::int64_t>;

constexpr char kBinaryMagic[] = "Kaydara FBX Binary";  // all Assimp compares (the two spaces after it not)
constexpr std::size_t kBinaryHeader = 27;              // magic, 0x00 0x1a 0x00, version (uint32)
constexpr int kMaxDepth = 256;

template <typename T>
bool read(const std::string& b, std::size_t at, T& out) {
    if (at > b.size() || sizeof(T) > b.size() - at) return false;
    std::memcpy(&out, b.data() + at, sizeof(T));  // FBX is little-endian, like the hosts we build for
    return true;
}

// Binary FBX: records of (end offset, property count, property bytes, name, properties, nested records).
class BinaryScan {
public:
    explicit BinaryScan(const std::string& bytes) : b_(bytes) {
        std::uint32_t version = 0;
        read(b_, 23, version);
        wide_ = version >= 7500;
    }

    void records(std::size_t at, std::size_t end, int depth) {
        while (depth < kMaxDepth && at < end) {
            std::uint64_t next = 0, count = 0, length = 0;
            std::uint8_t name_length = 0;
            const std::size_t word = wide_ ? 8 : 4;
            if (!number(at, next) || !number(at + word, count) || !number(at + 2 * word, length)) return;
            if (next == 0) return;  // the null record closing a list
            const std::size_t name_at = at + 3 * word + 1;
            if (next <= at || next > end || !read(b_, name_at - 1, name_length)) return;
            const std::size_t props = name_at + name_length;
            if (props <= b_.size() && length > b_.size() - props) overrun_ = at;
            if (props > next || length > next - props) return;
            if (name_length == 1 && b_[name_at] == 'C') connection(props, props + length);
            arrays(props, props + std::size_t(length), count);
            records(props + std::size_t(length), std::size_t(next), depth + 1);
            at = std::size_t(next);
        }
    }

    const std::vector<Edge>& edges() const { return edges_; }
    /// The largest length a zlib-compressed array declares beyond what its bytes can inflate to.
    std::optional<std::uint64_t> oversized() const { return oversized_; }
    /// The record whose property bytes run past the file's end, if any.
    std::optional<std::size_t> overrun() const { return overrun_; }

private:
    bool number(std::size_t at, std::uint64_t& out) const {
        if (wide_) return read(b_, at, out);
        std::uint32_t v = 0;
        if (!read(b_, at, v)) return false;
        out = v;
        return true;
    }

    // "C": a string ("OO", "OP", ...) then two 64-bit ids.
    void connection(std::size_t at, std::size_t end) {
        std::uint32_t length = 0;
        if (at >= end || b_[at] != 'S' || !read(b_, at + 1, length) || length > end - at - 5) return;
        at += 5 + length;
        std::int64_t ids[2];
        for (std::int64_t& id : ids) {
            if (at + 9 > end || b_[at] != 'L' || !read(b_, at + 1, id)) return;
            at += 9;
        }
        edges_.push_back({ids[0], ids[1]});
    }

    // A record's `count` properties: a type code, then a value of that type's size, or a length and that
    // many bytes (strings, raw data), or an array's (length, encoding, bytes) and its bytes. A zlib array
    // (encoding 1) whose length takes more bytes than deflate can give its compressed ones is noted:
    // Assimp allocates the length before it inflates (4 GB for a mutated length word; the plain arrays it
    // checks against their bytes itself). Stops at a type it does not know: the rest is Assimp's to judge.
    void arrays(std::size_t at, std::size_t end, std::uint64_t count) {
        for (std::uint64_t k = 0; k < count && at < end; ++k) {
            const char type = b_[at++];
            std::uint32_t length = 0, encoding = 0, bytes = 0;
            if (const std::size_t n = scalar_bytes(type)) {
                at += n;
            } else if (type == 'S' || type == 'R') {
                if (!read(b_, at, length)) return;
                at += 4 + std::size_t(length);
            } else if (const std::uint64_t stride = array_stride(type)) {
                if (!read(b_, at, length) || !read(b_, at + 4, encoding) || !read(b_, at + 8, bytes)) return;
                if (encoding == 1 && length * stride > kMaxInflation * bytes + kZlibFrame)
                    oversized_ = std::max(oversized_.value_or(0), std::uint64_t(length));
                at += 12 + std::size_t(bytes);
            } else {
                return;
            }
        }
    }

    // Bytes of a scalar property's value (bool, int16, int32, float, double, int64); 0 for other types.
    static std::size_t scalar_bytes(char type) {
        for (const auto& [t, n] : {std::pair{'C', 1}, {'Y', 2}, {'I', 4}, {'F', 4}, {'D', 8}, {'L', 8}})
            if (t == type) return std::size_t(n);
        return 0;
    }
    // Bytes of an array property's value (float, int32, double, int64, bool, char); 0 for other types.
    static std::uint64_t array_stride(char type) {
        for (const auto& [t, n] : {std::pair{'f', 4}, {'i', 4}, {'d', 8}, {'l', 8}, {'b', 1}, {'c', 1}})
            if (t == type) return std::uint64_t(n);
        return 0;
    }

    // Deflate gives at most 1,032 bytes per compressed byte (a 258-byte match in under two bits), after
    // zlib's 2-byte header and 4-byte checksum.
    static constexpr std::uint64_t kMaxInflation = 1032;
    static constexpr std::uint64_t kZlibFrame = 6 * kMaxInflation;

    const std::string& b_;
    std::vector<Edge> edges_;
    bool wide_ = false;
    std::optional<std::uint64_t> oversized_;
    std::optional<std::size_t> overrun_;
};

// ASCII FBX: tokens as Assimp cuts them (whitespace and commas separate, ';' comments to the end of the
// line, strings in double quotes, braces, a key ends with ':'). A "C" key followed by a string and two
// tokens that start with digits is a connection: Assimp reads an id's leading digits and ignores the
// rest of its token ("1001yy" is object 1001).
void ascii_scan(const std::string& s, std::vector<Edge>& edges) {
    struct Token {
        char kind;  // 'k' key, 's' string, 'd' data, '{', '}'
        std::string text;
    };
    std::vector<Token> pending;  // the "C" key and the tokens after it
    const auto flush = [&] {
        if (pending.size() >= 4 && pending[1].kind == 's' && pending[2].kind == 'd' && pending[3].kind == 'd') {
            const auto id = [](const std::string& t, std::int64_t& out) {
                const auto digit = [](char c) { return c >= '0' && c <= '9'; };
                const std::size_t digits = std::size_t(std::find_if_not(t.begin(), t.end(), digit) - t.begin());
                if (digits == 0 || digits > 20) return false;  // Assimp refuses those
                try {
                    out = static_cast<std::int64_t>(std::stoull(t.substr(0, digits)));  // unsigned 64-bit ids
                } catch (const std::out_of_range&) {
                    return false;
                }
                return true;
            };
            std::int64_t a = 0, b = 0;
            if (id(pending[2].text, a) && id(pending[3].text, b)) edges.push_back({a, b});
        }
        pending.clear();
    };
    const auto token = [&](char kind, std::string text) {
        if (kind == 'k' || kind == '{' || kind == '}') flush();
        if ((kind == 'k' && text == "C") || (!pending.empty() && pending.size() < 4))
            pending.push_back({kind, std::move(text)});
    };
    std::string word;
    const auto end_word = [&](bool key) {
        if (!word.empty()) token(key ? 'k' : 'd', word);
        word.clear();
    };
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == ';') {
            end_word(false);
            while (i < s.size() && s[i] != '\n') ++i;
        } else if (c == '"') {
            end_word(false);
            const std::size_t close = s.find('"', i + 1);
            if (close == std::string::npos) break;
            token('s', s.substr(i + 1, close - i - 1));
            i = close;
        } else if (c == ':') {
            end_word(true);
        } else if (c == '{' || c == '}') {
            end_word(false);
            token(c, {});
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',') {
            end_word(false);
        } else {
            word += c;
        }
    }
    end_word(false);
    flush();
}

// Depth-first search for a back edge, without recursion (a hostile file can chain many objects).
std::optional<std::int64_t> find_cycle(const std::vector<Edge>& edges) {
    std::unordered_map<std::int64_t, std::vector<std::int64_t>> out;
    for (const Edge& e : edges) out[e.first].push_back(e.second);
    std::unordered_map<std::int64_t, char> state;  // 0 unseen, 1 on the stack, 2 done
    for (const auto& start : out) {
        if (state[start.first]) continue;
        std::vector<std::pair<std::int64_t, std::size_t>> stack{{start.first, 0}};
        state[start.first] = 1;
        while (!stack.empty()) {
            auto& [v, next] = stack.back();
            const auto it = out.find(v);
            if (it == out.end() || next >= it->second.size()) {
                state[v] = 2;
                stack.pop_back();
                continue;
            }
            const std::int64_t w = it->second[next++];
            char& s = state[w];
            if (s == 1) return w;
            if (s == 0) {
                s = 1;
                stack.push_back({w, 0});
            }
        }
    }
    return std::nullopt;
}

// ASCII FBX: the first `*N` (an array's length, after a key) over the file's size in bytes, each value taking
// at least one; comments and strings skipped. N is capped at the size + 1: no overflow.
std::optional<std::uint64_t> ascii_impossible_array(const std::string& bytes) {
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const char c = bytes[i];
        if (c == ';') {  // a comment, to the end of the line
            while (i < bytes.size() && bytes[i] != '\n') ++i;
        } else if (c == '"') {  // a string
            i = bytes.find('"', i + 1);
            if (i == std::string::npos) break;
        } else if (c == '*') {
            std::uint64_t n = 0;
            bool digits = false;
            for (std::size_t k = i + 1; k < bytes.size() && bytes[k] >= '0' && bytes[k] <= '9'; ++k, digits = true)
                n = std::min<std::uint64_t>(n * 10 + std::uint64_t(bytes[k] - '0'), bytes.size() + 1);
            if (digits && n > bytes.size()) return n;
        }
    }
    return std::nullopt;
}

}  // namespace

Hazards hazards(const std::string& bytes) {
    if (bytes.compare(0, sizeof kBinaryMagic - 1, kBinaryMagic) == 0) {
        // The bytes as Assimp tokenizes them: the file and a NUL after it (a record may end on that NUL).
        const std::string read = bytes + '\0';
        BinaryScan scan(read);
        scan.records(kBinaryHeader, read.size(), 0);
        return {find_cycle(scan.edges()), scan.oversized(), scan.overrun()};
    }
    std::vector<Edge> edges;
    ascii_scan(bytes, edges);
    return {find_cycle(edges), ascii_impossible_array(bytes), std::nullopt};
}

bool names_property(const std::string& bytes, const std::string& name) {
    if (bytes.compare(0, sizeof kBinaryMagic - 1, kBinaryMagic) != 0)
        return bytes.find('"' + name + '"') != std::string::npos;
    std::string record = "S";
    const auto length = std::uint32_t(name.size());
    record.append(reinterpret_cast<const char*>(&length), 4);  // little-endian, like the hosts
    return bytes.find(record + name) != std::string::npos;
}

}  // namespace mobb::io::fbx
