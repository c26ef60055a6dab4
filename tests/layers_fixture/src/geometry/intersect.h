// Allowed by the layers (geometry 6 includes scene 5), but it closes the cycle with scene/record.h.
#pragma once
#include "scene/record.h"
