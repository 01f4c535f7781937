#include "bvh.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>

#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

#include "common.h"
#include "mobb/io/load.h"

namespace mobb::io::bvh {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

bool iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               const auto lower = [](char c) { return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c; };
               return lower(x) == lower(y);
           });
}

struct Token {
    std::string_view text;  // empty at the end of the input (or of the line, for next_on_line)
    int line = 0;
};

// Whitespace-separated tokens with 1-based line numbers. LF, CRLF and lone CR all end a line.
class Lexer {
public:
    Lexer(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    Token next() {
        skip_blanks(true);
        return take();
    }

    // The next token if it is on the current line, else an empty token (nothing consumed).
    Token next_on_line() {
        skip_blanks(false);
        return at_newline() ? Token{{}, line_} : take();
    }

    std::size_t remaining() const { return text_.size() - pos_; }
    int line() const { return line_; }

    [[noreturn]] void fail(int line, const std::string& message) const {
        throw LoadError(file_ + ":" + std::to_string(line) + ": " + message);
    }

private:
    bool at_newline() const {
        if (pos_ >= text_.size()) return true;
        const char c = text_[pos_];
        return c == '\n' || (c == '\r' && (pos_ + 1 == text_.size() || text_[pos_ + 1] != '\n'));
    }

    void skip_blanks(bool newlines) {
        while (pos_ < text_.size() && is_space(text_[pos_])) {
            if (at_newline()) {
                if (!newlines) return;
                ++line_;
            }
            ++pos_;
        }
    }

    Token take() {
        const std::size_t start = pos_;
        while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
        return {text_.substr(start, pos_ - start), line_};
    }

    std::string_view text_;
    const std::string& file_;
    std::size_t pos_ = 0;
    int line_ = 1;
};

std::string quoted(std::string_view text) {
    return text.empty() ? std::string("end of file") : "'" + detail::quote(text) + "'";
}

class Parser {
public:
    Parser(std::string_view text, const std::string& file) : lex_(text, file) {}

    Document run() {
        expect(lex_.next(), "HIERARCHY");
        const Token root = lex_.next();
        if (!iequals(root.text, "ROOT")) lex_.fail(root.line, "expected ROOT, found " + quoted(root.text));
        parse_hierarchy(root);
        parse_motion();
        return std::move(doc_);
    }

private:
    void expect(const Token& token, std::string_view keyword) {
        if (iequals(token.text, keyword)) return;
        const std::string what = keyword.size() == 1 ? "'" + std::string(keyword) + "'" : std::string(keyword);
        lex_.fail(token.line, "expected " + what + ", found " + quoted(token.text));
    }

    double number(const Token& token, std::string_view what) {
        std::string_view s = token.text;
        if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
        double value = 0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
        if (s.empty() || (ec != std::errc() && ec != std::errc::result_out_of_range) || end != s.data() + s.size())
            lex_.fail(token.line, "expected a number for " + std::string(what) + ", found " + quoted(token.text));
        // Out of range with a negative exponent is an underflow: as good as zero.
        const bool underflow = ec == std::errc::result_out_of_range &&
                               (s.find("e-") != std::string_view::npos || s.find("E-") != std::string_view::npos);
        if (underflow) return 0.0;
        if (ec == std::errc::result_out_of_range || !std::isfinite(value) || std::abs(value) > kMaxMagnitude)
            lex_.fail(token.line, "number " + quoted(token.text) + " for " + std::string(what) + " is out of range");
        return value;
    }

    std::int64_t integer(const Token& token, std::string_view what, std::int64_t lo, std::int64_t hi) {
        std::int64_t value = 0;
        const char* first = token.text.data();
        const char* last = first + token.text.size();
        const auto [end, ec] = std::from_chars(first, last, value);
        if (token.text.empty() || end != last || (ec != std::errc() && ec != std::errc::result_out_of_range))
            lex_.fail(token.line, "expected an integer for " + std::string(what) + ", found " + quoted(token.text));
        if (ec == std::errc::result_out_of_range || value < lo || value > hi)
            lex_.fail(token.line, std::string(what) + " " + quoted(token.text) + " is out of range " +
                                      std::to_string(lo) + ".." + std::to_string(hi));
        return value;
    }

    // "KEYWORD name words {" : the name is the rest of the line, the brace may share the line.
    std::string joint_name(const Token& keyword) {
        std::string name;
        bool brace = false;
        for (Token t = lex_.next_on_line(); !t.text.empty(); t = lex_.next_on_line()) {
            if (t.text == "{") {
                brace = true;
                break;
            }
            name += (name.empty() ? "" : " ") + std::string(t.text);
        }
        if (name.empty()) lex_.fail(keyword.line, std::string(keyword.text) + " needs a name on the same line");
        if (!brace) expect(lex_.next(), "{");
        return name;
    }

    glm::dvec3 offset() {
        expect(lex_.next(), "OFFSET");
        glm::dvec3 v;
        for (int i = 0; i < 3; ++i) v[i] = number(lex_.next(), "OFFSET");
        return v;
    }

    static bool channel_of(std::string_view name, Channel& out) {
        static constexpr std::array<std::string_view, 6> names = {"Xposition", "Yposition", "Zposition",
                                                                  "Xrotation", "Yrotation", "Zrotation"};
        for (std::size_t i = 0; i < names.size(); ++i)
            if (iequals(name, names[i])) {
                out = Channel(i);
                return true;
            }
        return false;
    }

    void channels(Joint& joint) {
        expect(lex_.next(), "CHANNELS");
        const Token count_token = lex_.next();
        const int count = int(integer(count_token, "channel count", 0, 6));
        for (int i = 0; i < count; ++i) {
            const Token t = lex_.next();
            Channel c{};
            if (!channel_of(t.text, c)) {
                const bool keyword = t.text.empty() || t.text == "{" || t.text == "}" || iequals(t.text, "JOINT") ||
                                     iequals(t.text, "End") || iequals(t.text, "MOTION");
                if (keyword)
                    lex_.fail(count_token.line, "CHANNELS " + std::to_string(count) + " lists only " +
                                                    std::to_string(i) + " channel names");
                lex_.fail(t.line, "unknown channel " + quoted(t.text));
            }
            if (std::find(joint.channels.begin(), joint.channels.end(), c) != joint.channels.end())
                lex_.fail(t.line, "channel " + quoted(t.text) + " is listed twice");
            joint.channels.push_back(c);
        }
        joint.first_value = doc_.channels;
        doc_.channels += count;
    }

    int add_joint(Joint joint, const Token& at) {
        if (int(doc_.joints.size()) >= kMaxJoints)
            lex_.fail(at.line, "more than " + std::to_string(kMaxJoints) + " joints");
        joint.line = at.line;
        doc_.joints.push_back(std::move(joint));
        return int(doc_.joints.size()) - 1;
    }

    // "NAME { OFFSET x y z CHANNELS n ... children }" after ROOT or JOINT: pushes the joint as open.
    void open_joint(const Token& keyword, int parent, std::vector<int>& open) {
        if (int(open.size()) >= kMaxDepth)
            lex_.fail(keyword.line, "joints nested deeper than " + std::to_string(kMaxDepth) + " levels");
        Joint joint;
        joint.name = joint_name(keyword);
        joint.parent = parent;
        joint.offset = offset();
        channels(joint);
        open.push_back(add_joint(std::move(joint), keyword));
    }

    // "End Site { OFFSET x y z }": a joint without channels or children.
    void end_site(const Token& keyword, int parent) {
        expect(lex_.next(), "Site");
        expect(lex_.next(), "{");
        Joint joint;
        joint.name = doc_.joints[std::size_t(parent)].name + " End Site";
        joint.parent = parent;
        joint.end_site = true;
        joint.offset = offset();
        expect(lex_.next(), "}");
        add_joint(std::move(joint), keyword);
    }

    // Iterative, with an explicit stack of open joints, so deep nesting cannot exhaust the call stack.
    void parse_hierarchy(const Token& root) {
        std::vector<int> open;
        open_joint(root, -1, open);
        while (!open.empty()) {
            const Token t = lex_.next();
            if (t.text == "}") {
                open.pop_back();
            } else if (iequals(t.text, "JOINT")) {
                open_joint(t, open.back(), open);
            } else if (iequals(t.text, "End")) {
                end_site(t, open.back());
            } else {
                const Joint& j = doc_.joints[std::size_t(open.back())];
                lex_.fail(t.line, "expected JOINT, End Site or '}' closing '" + detail::quote(j.name) + "' (line " +
                                      std::to_string(j.line) + "), found " + quoted(t.text));
            }
        }
    }

    // "NAME:" as one token or as "NAME" ":".
    void label(std::string_view name) {
        const Token t = lex_.next();
        if (iequals(t.text, std::string(name) + ":")) return;
        expect(t, name);
        expect(lex_.next(), ":");
    }

    void parse_motion() {
        const Token motion = lex_.next();
        if (iequals(motion.text, "ROOT")) lex_.fail(motion.line, "more than one ROOT is not supported");
        expect(motion, "MOTION");
        if (doc_.channels == 0) lex_.fail(motion.line, "the hierarchy has no channels");

        label("Frames");
        const Token frames = lex_.next();
        doc_.frames = int(integer(frames, "frame count", 1, std::numeric_limits<int>::max()));
        if (std::int64_t(doc_.frames) * std::int64_t(doc_.joints.size()) > detail::kMaxPositions)
            lex_.fail(frames.line, "Frames: " + std::to_string(doc_.frames) + " with " +
                                       std::to_string(doc_.joints.size()) + " joints is too large");

        expect(lex_.next(), "Frame");
        label("Time");
        const Token time = lex_.next();
        doc_.frame_time = number(time, "Frame Time");
        if (doc_.frame_time <= 0) lex_.fail(time.line, "Frame Time must be positive, found " + quoted(time.text));
        const Token extra = lex_.next_on_line();
        if (!extra.text.empty()) lex_.fail(extra.line, "unexpected " + quoted(extra.text) + " after Frame Time");

        parse_frames();
    }

    // One frame per line, exactly `channels` numbers each. Memory grows with the numbers actually read,
    // never with what the header promises.
    void parse_frames() {
        const auto per_frame = std::size_t(doc_.channels);
        const std::size_t promised = std::size_t(doc_.frames) * per_frame;
        doc_.values.reserve(std::min(promised, lex_.remaining() / 2 + 1));
        for (int f = 0; f < doc_.frames; ++f) {
            Token t = lex_.next();
            if (t.text.empty())
                lex_.fail(t.line,
                          "file ends after " + std::to_string(f) + " of " + std::to_string(doc_.frames) + " frames");
            const int line = t.line;
            std::size_t count = 0;
            for (; !t.text.empty(); t = lex_.next_on_line(), ++count) {
                if (count == per_frame)
                    lex_.fail(line, "frame " + std::to_string(f) + " has more than " + std::to_string(per_frame) +
                                        " numbers");
                doc_.values.push_back(number(t, "a channel"));
            }
            if (count < per_frame)
                lex_.fail(line, "frame " + std::to_string(f) + " has " + std::to_string(count) + " numbers, expected " +
                                    std::to_string(per_frame));
        }
        const Token extra = lex_.next();
        if (!extra.text.empty())
            lex_.fail(extra.line, "unexpected " + quoted(extra.text) +
                                      " after the last frame (Frames: " + std::to_string(doc_.frames) + ")");
    }

    Lexer lex_;
    Document doc_;
};

// Rotation by `degrees` about the channel's axis (right-handed, column vectors).
glm::dmat3 axis_rotation(Channel channel, double degrees) {
    const double a = glm::radians(degrees);
    const double c = std::cos(a);
    const double s = std::sin(a);
    glm::dmat3 m(1.0);  // m[column][row]
    switch (channel) {
        case Channel::Xrotation:
            m[1][1] = c;
            m[1][2] = s;
            m[2][1] = -s;
            m[2][2] = c;
            break;
        case Channel::Yrotation:
            m[0][0] = c;
            m[0][2] = -s;
            m[2][0] = s;
            m[2][2] = c;
            break;
        case Channel::Zrotation:
            m[0][0] = c;
            m[0][1] = s;
            m[1][0] = -s;
            m[1][1] = c;
            break;
        default: break;
    }
    return m;
}

// Per-joint world transforms of the frame being posed, reused across frames.
struct Scratch {
    std::vector<glm::dmat3> rotations;
    std::vector<glm::dvec3> world;
};

// World positions of one frame (values: that frame's channels), times `scale`, written to out[joint].
void pose(const Document& doc, const double* values, double scale, Scratch& scratch, glm::dvec3* out) {
    auto& rotations = scratch.rotations;
    auto& world = scratch.world;
    rotations.resize(doc.joints.size());
    world.resize(doc.joints.size());
    for (std::size_t j = 0; j < doc.joints.size(); ++j) {
        const Joint& joint = doc.joints[j];
        glm::dvec3 translation = joint.offset;
        glm::dmat3 rotation(1.0);
        for (std::size_t k = 0; k < joint.channels.size(); ++k) {
            const Channel c = joint.channels[k];
            const double v = values[std::size_t(joint.first_value) + k];
            if (c <= Channel::Zposition)
                translation[int(c)] += v;
            else
                rotation = rotation * axis_rotation(c, v);
        }
        if (joint.parent < 0) {
            world[j] = translation;
            rotations[j] = rotation;
        } else {
            const auto p = std::size_t(joint.parent);
            world[j] = world[p] + rotations[p] * translation;
            rotations[j] = rotations[p] * rotation;
        }
        out[j] = world[j] * scale;
    }
}

}  // namespace

Document parse(std::string_view text, const std::string& file) {
    if (text.size() >= std::size_t(std::numeric_limits<int>::max()))  // line numbers are ints
        throw LoadError(file + ":1: file too large for BVH");
    return Parser(text, file).run();
}

Animation animate(const Document& doc, double scale) {
    Animation anim;
    Skeleton& s = anim.skeleton;
    for (const Joint& j : doc.joints) {
        s.names.push_back(j.name);
        s.parents.push_back(j.parent);
        s.end_site.push_back(j.end_site);
    }
    s.root = 0;
    anim.dt = detail::snap_dt(doc.frame_time);
    const std::size_t joints = doc.joints.size();
    anim.positions.resize(std::size_t(doc.frames) * joints);
    Scratch scratch;
    for (std::size_t f = 0; f < std::size_t(doc.frames); ++f)
        pose(doc, doc.values.data() + f * std::size_t(doc.channels), scale, scratch,
             anim.positions.data() + f * joints);
    return anim;
}

}  // namespace mobb::io::bvh
