// Fixture for scripts/check_layers.py: the portability header, included by every layer.
#pragma once
