// What the viewer throws for bad input that is not a mocap file's fault: a scene file, a crowd record
// selection, a data folder that is missing. One line naming the file and the place.
#pragma once
#include <stdexcept>

namespace mobb::viewer {

class ViewerError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace mobb::viewer
