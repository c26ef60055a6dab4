#include "film/exr_file.h"

#include "io/atomic_file.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <vector>

namespace urbis {

namespace {

/// The channels of one file and the pixels behind them: float and uint channels point into the
/// caller's arrays, half channels into converted copies kept here until the file is written.
class ExrChannels {
public:
    ExrChannels(uint32_t width, uint32_t height) : width_(width), height_(height), header_(int(width), int(height)) {
        header_.compression() = Imf::ZIP_COMPRESSION;
    }

    /// Channel `name` from the floats at `first`, `stride` bytes apart, as half or float.
    void addFloat(const char* name, const float* first, size_t stride, bool asHalf) {
        if (!asHalf) return insert(name, Imf::FLOAT, first, stride);
        auto& halves = halves_.emplace_back(std::make_unique<Imath::half[]>(pixels()));
        const char* bytes = reinterpret_cast<const char*>(first);
        for (size_t i = 0; i < pixels(); ++i) halves[i] = Imath::half(*reinterpret_cast<const float*>(bytes + i * stride));
        insert(name, Imf::HALF, halves.get(), sizeof(Imath::half));
    }
    /// Channels `prefix` + each of `suffixes` from the components of `vectors`.
    void addVec3(const std::string& prefix, const char* const (&suffixes)[3], const std::vector<Vec3f>& vectors,
                 bool asHalf) {
        for (int c = 0; c < 3; ++c)
            addFloat((prefix + suffixes[c]).c_str(), &vectors[0].x + c, sizeof(Vec3f), asHalf);
    }
    void addUint(const char* name, const std::vector<uint32_t>& values) {
        insert(name, Imf::UINT, values.data(), sizeof(uint32_t));
    }

    /// Encodes every channel into `stream`; throws what OpenEXR throws.
    void write(std::ofstream& stream, const std::string& name) {
        Imf::StdOFStream out(stream, name.c_str());
        Imf::OutputFile file(out, header_);
        file.setFrameBuffer(frame_);
        file.writePixels(int(height_));
    }

private:
    size_t pixels() const { return size_t(width_) * height_; }
    void insert(const char* name, Imf::PixelType type, const void* first, size_t stride) {
        header_.channels().insert(name, Imf::Channel(type));
        frame_.insert(name, Imf::Slice(type, static_cast<char*>(const_cast<void*>(first)), stride, stride * width_));
    }

    uint32_t width_, height_;
    Imf::Header header_;
    Imf::FrameBuffer frame_;
    std::vector<std::unique_ptr<Imath::half[]>> halves_;
};

/// The first line of `text`: OpenEXR's messages are one line, but the user must see exactly one.
std::string firstLine(const char* text) {
    std::string line(text);
    return line.substr(0, line.find('\n'));
}

} // namespace

void writeExr(const Film& film, const std::string& path, const ExrOptions& options) {
    LinearImage radiance = meanRadiance(film);
    for (Vec3f& p : radiance.pixels) p *= options.exposureScale;
    const std::vector<float> alpha(film.pixels(), 1.0f);
    const bool half = !options.floatColour;
    ExrChannels channels(film.width, film.height);
    channels.addVec3("", {"R", "G", "B"}, radiance.pixels, half);
    channels.addFloat("A", alpha.data(), sizeof(float), half);
    AovImages aovs;
    if (film.hasAovs()) {
        aovs = resolveAovs(film);
        const uint32_t layers = options.layers;
        if (layers & kAlbedoLayer) channels.addVec3("albedo.", {"R", "G", "B"}, aovs.albedo, half);
        if (layers & kNormalLayer) channels.addVec3("normal.", {"X", "Y", "Z"}, aovs.normal, half);
        // Metres at city scale need float: half steps by 2 m between 2 and 4 km.
        if (layers & kPositionLayer) channels.addVec3("position.", {"X", "Y", "Z"}, aovs.position, false);
        if (layers & kDepthLayer) channels.addFloat("depth.Z", aovs.depth.data(), sizeof(float), false);
        if (layers & kIdLayer) {
            channels.addUint("id.object", aovs.object);
            channels.addUint("id.part", aovs.part);
        }
        if (layers & kSamplesLayer) channels.addUint("samples", aovs.samples);
    }

    writeThroughTemporary(path, [&](const std::string& temporary) -> std::string {
        std::ofstream stream(temporary, std::ios::binary);
        if (!stream) return std::string("cannot write: ") + std::strerror(errno);
        try {
            channels.write(stream, temporary);
        } catch (const std::exception& e) {
            return "failed to write EXR data: " + firstLine(e.what());
        }
        stream.close();
        return stream.fail() ? "failed to write EXR data" : "";
    });
}

size_t exrWriteBytes(uint32_t width, uint32_t height) {
    const size_t pixels = size_t(width) * height;
    const size_t radianceAndAlpha = sizeof(Vec3f) + sizeof(float);
    const size_t resolvedAovs = 3 * sizeof(Vec3f) + sizeof(float) + 3 * sizeof(uint32_t);
    const size_t halfCopies = 10 * sizeof(Imath::half);   // RGBA, albedo and normal
    return pixels * (radianceAndAlpha + resolvedAovs + halfCopies);
}

} // namespace urbis
