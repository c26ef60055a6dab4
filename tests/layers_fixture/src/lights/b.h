#pragma once
#include "lights/c.h"
