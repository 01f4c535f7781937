// The escape table moved to plan/escape.h (the reservation model, below the rules and the choice point);
// this name stays for the files outside the choice point that include it (scenario/steersuite.cpp) until
// they include plan/escape.h.
#pragma once
#include "plan/escape.h"
