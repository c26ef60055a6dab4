// Rejected: cpu/ and gpu/ share rank 14 and may not include each other.
#pragma once
#include "gpu/backend.h"
