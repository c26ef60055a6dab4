// Rejected: a file directly in src/ other than urbis.h is in no layer.
#pragma once
