// `urbis view --headless --device cuda`: the progressive film kept on the GPU, one sample a frame,
// and denoised while young by the GPU's filter (the device film then restored to its sums), is
// `urbis render --device cuda` of the same scene. Tolerance: none; both add the same samples with
// the same kernels in the same order, and the denoiser's picture never touches the sums.
#include "cli_support.h"
#include "gpu_test_support.h"

using namespace urbis::test;

TEST(GpuView, ProgressiveFramesDenoisedWhileYoungAreTheGpuRender) {
    URBIS_SKIP_WITHOUT_GPU();
    auto dir = scratchDir("gpu_view");
    std::ofstream(dir / "undenoise.json") << R"({"steps": [{"frame": 4, "set": {"film": {"denoise": false}}}]})";
    CommandResult view = runUrbis("view --headless --device cuda --width 96 --height 54 --buildings 40 --spp 4 --frames 5 "
                                  "--denoise --script undenoise.json --screenshot view.png --save-scene view.json --stats s.json",
                                  dir);
    ASSERT_EQ(view.exitCode, 0) << view.err;
    EXPECT_NE(view.out.find("on cuda"), std::string::npos) << view.out;
    CommandResult render = runUrbis("render --device cuda --scene view.json --out render.png", dir);
    ASSERT_EQ(render.exitCode, 0) << render.err;
    EXPECT_EQ(readFile(dir / "view.png"), readFile(dir / "render.png"));
}
