// Rejected: extras/ is not in the layer table.
#pragma once
#include "math/vec.h"
