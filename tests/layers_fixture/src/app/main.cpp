// Allowed: app/ (14) includes a backend. Rejected: an include that names no file under src/.
#include "cpu/renderer.h"
#include "app/missing.h"
