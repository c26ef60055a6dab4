#pragma once
#include "scene/record.h"
