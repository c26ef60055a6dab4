// Rejected: scene/ (5) includes geometry/ (6); and the two headers include each other (a cycle).
#pragma once
#include "math/vec.h"
#include "geometry/intersect.h"
