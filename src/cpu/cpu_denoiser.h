// The denoiser on the CPU: the passes of film/denoise_filter.h over TBB's thread pool.
#pragma once

#include "film/denoise_filter.h"
#include "film/film.h"

namespace urbis {

/// Denoises `film` (which keeps AOVs) in place with the SVGF spatial filter (film/denoise_filter.h):
/// its radiance sums become the denoised mean times the sample count, the sky's stay as they were.
/// Every pixel is a function of the passes before, so the result is the same for any thread count.
/// The film then holds no unbiased sums: denoise a copy to go on adding samples.
void denoiseCpu(Film& film, const DenoiseParams& params = {});

} // namespace urbis
