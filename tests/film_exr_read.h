// Reading an EXR file back with OpenEXR's own reader, for the film's tests.
#pragma once

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace urbis::test {

/// An EXR file read back: each channel's type and its pixels as float or uint.
struct ExrRead {
    int width = 0, height = 0;
    std::map<std::string, Imf::PixelType> types;
    std::map<std::string, std::vector<float>> floats;
    std::map<std::string, std::vector<uint32_t>> uints;
};

inline ExrRead readExr(const std::string& path) {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    ExrRead out;
    out.width = window.max.x - window.min.x + 1;
    out.height = window.max.y - window.min.y + 1;
    const size_t n = size_t(out.width) * out.height;
    Imf::FrameBuffer frame;
    for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c) {
        const std::string name = c.name();
        out.types[name] = c.channel().type;
        if (c.channel().type == Imf::UINT) {
            auto& v = out.uints[name] = std::vector<uint32_t>(n);
            frame.insert(name, Imf::Slice(Imf::UINT, reinterpret_cast<char*>(v.data()), 4, 4 * size_t(out.width)));
        } else {
            auto& v = out.floats[name] = std::vector<float>(n);
            frame.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data()), 4, 4 * size_t(out.width)));
        }
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return out;
}

} // namespace urbis::test
