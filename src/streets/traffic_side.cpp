#include "streets/traffic_side.h"

namespace urbis {

namespace {

/// A box of latitudes and longitudes, degrees.
struct GeoBox {
    double south, north, west, east;
};

/// Left-hand traffic. Where a box would reach a right-hand neighbour it is cut short of it: Great
/// Britain's box stops east at 1.8 degrees (Calais lies at 1.85), Honshu's west at 129.5 (Busan at
/// 129.0), India's east north at 28.1 (Lhasa at 29.65), Hong Kong's north at 22.5 (Shenzhen).
constexpr GeoBox kLeftHand[] = {
    {49.8, 61.0, -10.7, 1.8},      // Great Britain, Ireland
    {35.78, 36.09, 14.17, 14.58},  // Malta
    {34.5, 35.75, 32.2, 34.65},    // Cyprus
    {30.0, 41.6, 129.5, 142.2},    // Kyushu, Shikoku, Honshu
    {41.3, 45.6, 139.3, 146.0},    // Hokkaido
    {24.0, 30.0, 122.9, 131.4},    // Okinawa and the Ryukyu islands
    {22.1, 22.5, 113.5, 114.45},   // Hong Kong, Macau
    {6.0, 30.0, 68.0, 81.0},       // India's west, Sri Lanka
    {6.0, 28.1, 81.0, 92.0},       // India's east, Nepal, Bhutan, Bangladesh
    {24.0, 33.8, 70.5, 75.5},      // Pakistan's east (Lahore, Islamabad)
    {5.6, 14.5, 99.6, 102.3},      // Thailand's south (Bangkok)
    {-11.0, 7.4, 95.0, 119.3},     // Malaysia, Singapore, Brunei, western Indonesia
    {-11.0, 2.0, 119.3, 155.0},    // eastern Indonesia, Timor, Papua New Guinea
    {-44.0, -10.0, 112.0, 154.0},  // Australia
    {-48.0, -34.0, 166.0, 179.0},  // New Zealand
    {-35.0, -17.0, 11.5, 41.0},    // South Africa, Namibia, Botswana, Zimbabwe, Mozambique
    {-11.7, 4.6, 30.9, 41.0},      // Kenya, Tanzania, Uganda
    {17.7, 18.6, -78.4, -76.2},    // Jamaica
};

} // namespace

TrafficSide trafficSideAt(double latitude, double longitude) {
    for (const GeoBox& b : kLeftHand)
        if (latitude >= b.south && latitude <= b.north && longitude >= b.west && longitude <= b.east)
            return TrafficSide::Left;
    return TrafficSide::Right;
}

TrafficSide trafficSideOf(const GeoOrigin& origin) {
    return origin.valid ? trafficSideAt(origin.lat, origin.lon) : TrafficSide::Right;
}

} // namespace urbis
