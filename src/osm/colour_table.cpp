#include "osm/colour_table.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>
#include <utility>

namespace urbis {

namespace {

// CSS Color 3 names (https://www.w3.org/TR/css-color-3/, as OSM colour tags use them), plus
// OSM's own cream, light_brown, dark_brown, brick_red and yellow-brown; sRGB, sorted by
// name for binary search.
constexpr std::array<std::pair<std::string_view, uint32_t>, 152> kNamedColours = {{
    {"aliceblue", 0xf0f8ff}, {"antiquewhite", 0xfaebd7}, {"aqua", 0x00ffff},
    {"aquamarine", 0x7fffd4}, {"azure", 0xf0ffff}, {"beige", 0xf5f5dc},
    {"bisque", 0xffe4c4}, {"black", 0x000000}, {"blanchedalmond", 0xffebcd},
    {"blue", 0x0000ff}, {"blueviolet", 0x8a2be2}, {"brickred", 0xcb4154},
    {"brown", 0xa52a2a}, {"burlywood", 0xdeb887}, {"cadetblue", 0x5f9ea0},
    {"chartreuse", 0x7fff00}, {"chocolate", 0xd2691e}, {"coral", 0xff7f50},
    {"cornflowerblue", 0x6495ed}, {"cornsilk", 0xfff8dc}, {"cream", 0xfffdd0},
    {"crimson", 0xdc143c}, {"cyan", 0x00ffff}, {"darkblue", 0x00008b},
    {"darkbrown", 0x654321}, {"darkcyan", 0x008b8b}, {"darkgoldenrod", 0xb8860b},
    {"darkgray", 0xa9a9a9}, {"darkgreen", 0x006400}, {"darkgrey", 0xa9a9a9},
    {"darkkhaki", 0xbdb76b}, {"darkmagenta", 0x8b008b}, {"darkolivegreen", 0x556b2f},
    {"darkorange", 0xff8c00}, {"darkorchid", 0x9932cc}, {"darkred", 0x8b0000},
    {"darksalmon", 0xe9967a}, {"darkseagreen", 0x8fbc8f}, {"darkslateblue", 0x483d8b},
    {"darkslategray", 0x2f4f4f}, {"darkslategrey", 0x2f4f4f}, {"darkturquoise", 0x00ced1},
    {"darkviolet", 0x9400d3}, {"deeppink", 0xff1493}, {"deepskyblue", 0x00bfff},
    {"dimgray", 0x696969}, {"dimgrey", 0x696969}, {"dodgerblue", 0x1e90ff},
    {"firebrick", 0xb22222}, {"floralwhite", 0xfffaf0}, {"forestgreen", 0x228b22},
    {"fuchsia", 0xff00ff}, {"gainsboro", 0xdcdcdc}, {"ghostwhite", 0xf8f8ff},
    {"gold", 0xffd700}, {"goldenrod", 0xdaa520}, {"gray", 0x808080},
    {"green", 0x008000}, {"greenyellow", 0xadff2f}, {"grey", 0x808080},
    {"honeydew", 0xf0fff0}, {"hotpink", 0xff69b4}, {"indianred", 0xcd5c5c},
    {"indigo", 0x4b0082}, {"ivory", 0xfffff0}, {"khaki", 0xf0e68c},
    {"lavender", 0xe6e6fa}, {"lavenderblush", 0xfff0f5}, {"lawngreen", 0x7cfc00},
    {"lemonchiffon", 0xfffacd}, {"lightblue", 0xadd8e6}, {"lightbrown", 0xc4a484},
    {"lightcoral", 0xf08080}, {"lightcyan", 0xe0ffff}, {"lightgoldenrodyellow", 0xfafad2},
    {"lightgray", 0xd3d3d3}, {"lightgreen", 0x90ee90}, {"lightgrey", 0xd3d3d3},
    {"lightpink", 0xffb6c1}, {"lightsalmon", 0xffa07a}, {"lightseagreen", 0x20b2aa},
    {"lightskyblue", 0x87cefa}, {"lightslategray", 0x778899}, {"lightslategrey", 0x778899},
    {"lightsteelblue", 0xb0c4de}, {"lightyellow", 0xffffe0}, {"lime", 0x00ff00},
    {"limegreen", 0x32cd32}, {"linen", 0xfaf0e6}, {"magenta", 0xff00ff},
    {"maroon", 0x800000}, {"mediumaquamarine", 0x66cdaa}, {"mediumblue", 0x0000cd},
    {"mediumorchid", 0xba55d3}, {"mediumpurple", 0x9370db}, {"mediumseagreen", 0x3cb371},
    {"mediumslateblue", 0x7b68ee}, {"mediumspringgreen", 0x00fa9a}, {"mediumturquoise", 0x48d1cc},
    {"mediumvioletred", 0xc71585}, {"midnightblue", 0x191970}, {"mintcream", 0xf5fffa},
    {"mistyrose", 0xffe4e1}, {"moccasin", 0xffe4b5}, {"navajowhite", 0xffdead},
    {"navy", 0x000080}, {"oldlace", 0xfdf5e6}, {"olive", 0x808000},
    {"olivedrab", 0x6b8e23}, {"orange", 0xffa500}, {"orangered", 0xff4500},
    {"orchid", 0xda70d6}, {"palegoldenrod", 0xeee8aa}, {"palegreen", 0x98fb98},
    {"paleturquoise", 0xafeeee}, {"palevioletred", 0xdb7093}, {"papayawhip", 0xffefd5},
    {"peachpuff", 0xffdab9}, {"peru", 0xcd853f}, {"pink", 0xffc0cb},
    {"plum", 0xdda0dd}, {"powderblue", 0xb0e0e6}, {"purple", 0x800080},
    {"red", 0xff0000}, {"rosybrown", 0xbc8f8f}, {"royalblue", 0x4169e1},
    {"saddlebrown", 0x8b4513}, {"salmon", 0xfa8072}, {"sandybrown", 0xf4a460},
    {"seagreen", 0x2e8b57}, {"seashell", 0xfff5ee}, {"sienna", 0xa0522d},
    {"silver", 0xc0c0c0}, {"skyblue", 0x87ceeb}, {"slateblue", 0x6a5acd},
    {"slategray", 0x708090}, {"slategrey", 0x708090}, {"snow", 0xfffafa},
    {"springgreen", 0x00ff7f}, {"steelblue", 0x4682b4}, {"tan", 0xd2b48c},
    {"teal", 0x008080}, {"thistle", 0xd8bfd8}, {"tomato", 0xff6347},
    {"turquoise", 0x40e0d0}, {"violet", 0xee82ee}, {"wheat", 0xf5deb3},
    {"white", 0xffffff}, {"whitesmoke", 0xf5f5f5}, {"yellow", 0xffff00},
    {"yellowbrown", 0xb8860b}, {"yellowgreen", 0x9acd32}}};

constexpr std::array<std::pair<BuildingMaterial, uint32_t>, 9> kMaterialColours = {{
    {BuildingMaterial::Brick, 0x9c4a32}, {BuildingMaterial::Concrete, 0xb5b2ab},
    {BuildingMaterial::Glass, 0x6f8fa6}, {BuildingMaterial::Metal, 0x9ea3a8},
    {BuildingMaterial::Plaster, 0xe6dccb}, {BuildingMaterial::Stone, 0xb8ae9c},
    {BuildingMaterial::Wood, 0x8b6a48}, {BuildingMaterial::Sandstone, 0xd2b98b},
    {BuildingMaterial::Timber, 0xe8e0d0}}};

// roof:material values (https://wiki.openstreetmap.org/wiki/Key:roof:material, and the
// spellings mappers use beside them), as weathered surfaces look from the street.
constexpr std::array<std::pair<std::string_view, uint32_t>, 28> kRoofMaterialColours = {{
    {"roof_tiles", 0x8e4b38}, {"tile", 0x8e4b38}, {"tiles", 0x8e4b38}, {"clay", 0x8e4b38},
    {"slate", 0x4a4e55}, {"metal", 0x8e9399}, {"metal_sheet", 0x8e9399}, {"zinc", 0x8c9296},
    {"lead", 0x6e7378}, {"copper", 0x6fa58c}, {"concrete", 0xa9a69f}, {"gravel", 0x9a958c},
    {"tar_paper", 0x3c3c3c}, {"asphalt", 0x3c3c3c}, {"bitumen", 0x3c3c3c},
    {"asphalt_shingle", 0x55524e}, {"glass", 0x7f9db3}, {"acrylic_glass", 0x8fa8b8},
    {"grass", 0x5d7a3e}, {"plants", 0x5d7a3e}, {"eternit", 0x8a8c8a}, {"asbestos", 0x9a9a94},
    {"thatch", 0xb39a62}, {"stone", 0x8e8a80}, {"wood", 0x7a5e44}, {"plastic", 0xb8b8b4},
    {"membrane", 0xc8c8c2}, {"solar_panels", 0x27303c}}};

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    c = char(std::tolower(static_cast<unsigned char>(c)));
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

std::optional<Rgb> parseHex(std::string_view hex) {
    uint32_t rgb = 0;
    for (char c : hex) {
        const int d = hexDigit(c);
        if (d < 0) return std::nullopt;
        rgb = rgb << 4 | uint32_t(d);
    }
    if (hex.size() == 3) // #rgb -> #rrggbb
        rgb = ((rgb >> 8) & 0xf) * 0x110000 | ((rgb >> 4) & 0xf) * 0x1100 | (rgb & 0xf) * 0x11;
    else if (hex.size() != 6)
        return std::nullopt;
    return fromSrgbHex(rgb);
}

} // namespace

float linearFromSrgb(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

Rgb fromSrgbHex(uint32_t rgb) {
    return {linearFromSrgb(float((rgb >> 16) & 0xff) / 255.0f),
            linearFromSrgb(float((rgb >> 8) & 0xff) / 255.0f),
            linearFromSrgb(float(rgb & 0xff) / 255.0f)};
}

std::optional<Rgb> parseColour(std::string_view value) {
    if (!value.empty() && value.front() == '#') return parseHex(value.substr(1));
    std::string name;
    for (char c : value)
        if (c != ' ' && c != '_' && c != '-') name += char(std::tolower(static_cast<unsigned char>(c)));
    const auto it = std::lower_bound(kNamedColours.begin(), kNamedColours.end(), std::string_view(name),
                                     [](const auto& entry, std::string_view key) { return entry.first < key; });
    if (it == kNamedColours.end() || it->first != name) return std::nullopt;
    return fromSrgbHex(it->second);
}

std::optional<Rgb> materialColour(BuildingMaterial material) {
    for (const auto& [m, rgb] : kMaterialColours)
        if (m == material) return fromSrgbHex(rgb);
    return std::nullopt;
}

std::optional<Rgb> roofMaterialColour(std::string_view roofMaterial) {
    for (const auto& [name, rgb] : kRoofMaterialColours)
        if (name == roofMaterial) return fromSrgbHex(rgb);
    return std::nullopt;
}

} // namespace urbis
