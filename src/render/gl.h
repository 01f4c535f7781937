// Every GL call in the project goes through this one loader (glad, generated at build time), so the
// same code draws into a GLFW window and into an OSMesa buffer.
#pragma once
#include <glad/gl.h>
