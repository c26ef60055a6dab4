// A cycle of three inside one folder; "b.h" resolves beside this file, as the compiler resolves it.
#pragma once
#include "b.h"
