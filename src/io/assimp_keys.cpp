#include "assimp_keys.h"

#include <algorithm>
#include <cmath>

#include "mobb/io/load.h"

namespace mobb::io::assimp {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

glm::dvec3 blend(const glm::dvec3& a, const glm::dvec3& b, double u) { return a * (1 - u) + b * u; }
glm::dquat blend(const glm::dquat& a, const glm::dquat& b, double u) { return glm::normalize(glm::slerp(a, b, u)); }

bool same(const glm::dvec3& a, const glm::dvec3& b) { return a == b; }
bool same(const glm::dquat& a, const glm::dquat& b) { return a == b || a == -b; }

template <typename Key>
void read_times(const Key* keys, unsigned count, double tps, std::vector<double>& times, const std::string& where) {
    times.reserve(count);
    for (unsigned k = 0; k < count; ++k) {
        const double t = keys[k].mTime / tps;
        if (!std::isfinite(t)) throw LoadError(where + ": key " + std::to_string(k) + " has a non-finite time");
        if (!times.empty() && t < times.back())
            throw LoadError(where + ": key times decrease at key " + std::to_string(k));
        times.push_back(t);
    }
}

void read_vectors(const aiVectorKey* keys, unsigned count, double tps, Keys<glm::dvec3>& out,
                  const std::string& where) {
    if (!keys) return;
    read_times(keys, count, tps, out.times, where);
    for (unsigned k = 0; k < count; ++k) {
        const glm::dvec3 v(keys[k].mValue.x, keys[k].mValue.y, keys[k].mValue.z);
        if (!finite(v)) throw LoadError(where + ": key " + std::to_string(k) + " is not finite");
        out.values.push_back(v);
    }
}

void read_rotations(const aiQuatKey* keys, unsigned count, double tps, Keys<glm::dquat>& out,
                    const std::string& where) {
    if (!keys) return;
    read_times(keys, count, tps, out.times, where);
    for (unsigned k = 0; k < count; ++k) {
        const aiQuaternion& q = keys[k].mValue;
        const glm::dquat v(q.w, q.x, q.y, q.z);
        const double length = glm::length(v);
        if (!(length > 0) || !std::isfinite(length))
            throw LoadError(where + ": rotation key " + std::to_string(k) + " is zero or not finite");
        out.values.push_back(v / length);
    }
}

}  // namespace

template <typename Value>
bool Keys<Value>::changes() const {
    for (std::size_t k = 1; k < values.size(); ++k)
        if (!same(values[k], values[0])) return true;
    return false;
}

template <typename Value>
Value Keys<Value>::at(double time) const {
    if (time <= times.front()) return values.front();
    if (time >= times.back()) return values.back();
    const auto k = std::size_t(std::upper_bound(times.begin(), times.end(), time) - times.begin()) - 1;
    double u = (time - times[k]) / (times[k + 1] - times[k]);
    // Sample times are multiples of the frame time while keys carry rounding: land on a key when that close.
    if (u < 1e-3) u = 0;
    if (u > 1 - 1e-3) u = 1;
    return blend(values[k], values[k + 1], u);
}

template struct Keys<glm::dvec3>;
template struct Keys<glm::dquat>;

glm::dmat4 Track::at(double time, const aiMatrix4x4& rest) const {
    aiVector3D rest_scale, rest_position;
    aiQuaternion rest_rotation;
    if (translation.times.empty() || rotation.times.empty() || scale.times.empty())
        rest.Decompose(rest_scale, rest_rotation, rest_position);
    const glm::dvec3 t = translation.times.empty() ? glm::dvec3(rest_position.x, rest_position.y, rest_position.z)
                                                   : translation.at(time);
    const glm::dquat r =
        rotation.times.empty()
            ? glm::normalize(glm::dquat(rest_rotation.w, rest_rotation.x, rest_rotation.y, rest_rotation.z))
            : rotation.at(time);
    const glm::dvec3 s = scale.times.empty() ? glm::dvec3(rest_scale.x, rest_scale.y, rest_scale.z) : scale.at(time);
    const glm::dmat3 m = glm::mat3_cast(r);
    glm::dmat4 out(1.0);
    for (int c = 0; c < 3; ++c) out[c] = glm::dvec4(m[c] * s[c], 0.0);
    out[3] = glm::dvec4(t, 1.0);
    return out;
}

Track read_track(const aiNodeAnim& channel, double tps, const std::string& where) {
    Track track;
    read_vectors(channel.mPositionKeys, channel.mNumPositionKeys, tps, track.translation, where + " position");
    read_rotations(channel.mRotationKeys, channel.mNumRotationKeys, tps, track.rotation, where + " rotation");
    read_vectors(channel.mScalingKeys, channel.mNumScalingKeys, tps, track.scale, where + " scaling");
    return track;
}

}  // namespace mobb::io::assimp
