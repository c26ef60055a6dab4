// Allowed: math/ (rank 0) includes the portability header of its own rank.
#pragma once
#include "urbis.h"
