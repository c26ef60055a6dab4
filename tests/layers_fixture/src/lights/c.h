#pragma once
#include "lights/a.h"
