#include "citygen/facade_style.h"

#include "math/hash.h"

namespace urbis {

namespace {

/// Defaults per building type; the seed then varies sizes within a few tens of centimetres.
struct TypeRow {
    BuildingType type;
    bool hasFacade;
    float floorHeight, slotWidth, windowFraction, windowHeight, sillHeight;
    float curtainChance;   ///< of a glazed curtain wall (only where the building is tall enough)
    float balconyChance;   ///< of balconies on the building
    bool shopFront;
};

// Balconies only where people live (homes, flats, hotels): never on churches, towers, halls,
// offices, shops or schools. Generic (`building=yes` whose use tags name no type, see
// buildingTypeFromTags) gets none either: it covers church towers, offices and sheds as often
// as flats, and a balcony on a spire looks wrong where a missing one on a block of flats
// goes unnoticed.
constexpr TypeRow kRows[] = {
    // type                      facade floor  slot  frac  winH  sill  curtain balcony shop
    {BuildingType::Generic,      true,  3.2f, 3.0f, 0.45f, 1.5f, 0.9f, 0.0f,  0.0f,  false},
    {BuildingType::Residential,  true,  3.0f, 3.0f, 0.45f, 1.5f, 0.9f, 0.0f,  0.5f,  false},
    {BuildingType::House,        true,  3.0f, 3.5f, 0.40f, 1.3f, 0.9f, 0.0f,  0.1f,  false},
    {BuildingType::Apartments,   true,  3.0f, 3.0f, 0.45f, 1.5f, 0.9f, 0.0f,  0.6f,  false},
    {BuildingType::Commercial,   true,  3.6f, 3.0f, 0.60f, 1.9f, 0.8f, 0.4f,  0.0f,  true},
    {BuildingType::Retail,       true,  3.6f, 3.2f, 0.55f, 1.7f, 0.9f, 0.0f,  0.0f,  true},
    {BuildingType::Office,       true,  3.6f, 2.6f, 0.60f, 1.9f, 0.8f, 0.7f,  0.0f,  false},
    {BuildingType::Industrial,   true,  4.5f, 4.0f, 0.60f, 1.2f, 2.6f, 0.0f,  0.0f,  false},
    {BuildingType::Warehouse,    true,  4.5f, 4.0f, 0.60f, 1.2f, 2.6f, 0.0f,  0.0f,  false},
    {BuildingType::Religious,    true,  4.0f, 3.5f, 0.35f, 2.2f, 1.2f, 0.0f,  0.0f,  false},
    {BuildingType::Civic,        true,  3.6f, 3.0f, 0.50f, 1.8f, 0.9f, 0.2f,  0.0f,  false},
    {BuildingType::School,       true,  3.6f, 3.0f, 0.60f, 1.8f, 0.9f, 0.0f,  0.0f,  false},
    {BuildingType::Hospital,     true,  3.6f, 3.0f, 0.50f, 1.6f, 0.9f, 0.1f,  0.0f,  false},
    {BuildingType::Hotel,        true,  3.2f, 3.2f, 0.50f, 1.7f, 0.8f, 0.3f,  0.5f,  true},
    {BuildingType::Garage,       false, 3.0f, 3.0f, 0.50f, 1.5f, 0.9f, 0.0f,  0.0f,  false},
    {BuildingType::Shed,         false, 3.0f, 3.0f, 0.50f, 1.5f, 0.9f, 0.0f,  0.0f,  false},
    {BuildingType::Roof,         false, 3.0f, 3.0f, 0.50f, 1.5f, 0.9f, 0.0f,  0.0f,  false},
};

const TypeRow& rowOf(BuildingType type) {
    for (const TypeRow& row : kRows)
        if (row.type == type) return row;
    return kRows[0];
}

/// Curtain walls need a few floors to read as such.
constexpr float kMinCurtainHeight = 15.0f;

} // namespace

FacadeStyle facadeStyleOf(const Building& building) {
    const TypeRow& row = rowOf(building.type);
    HashStream rng{hash2(building.seed, 0x46616361u)};   // "Faca"
    FacadeStyle s;
    s.hasFacade = row.hasFacade;
    s.floorHeight = row.floorHeight + rng.uniform(-0.1f, 0.3f);
    s.slotWidth = row.slotWidth * rng.uniform(0.85f, 1.25f);
    s.windowFraction = row.windowFraction * rng.uniform(0.85f, 1.15f);
    s.windowHeight = row.windowHeight * rng.uniform(0.9f, 1.1f);
    s.sillHeight = row.sillHeight;
    const float wallHeight = building.height - building.minHeight;
    const bool glass = building.material == BuildingMaterial::Glass;
    const bool curtain = (glass || rng.uniform() < row.curtainChance) && row.curtainChance > 0.0f &&
                         wallHeight >= kMinCurtainHeight;
    if (curtain) {
        s.style = WallStyle::Curtain;
        s.slotWidth = rng.uniform(2.5f, 3.2f);
        s.sillHeight = rng.uniform(0.8f, 1.1f);
        s.reveal = 0.1f;
        return s;
    }
    if (rng.uniform() < row.balconyChance) s.flags |= kWallBalconies;
    if (row.shopFront) s.flags |= kWallShopFront;
    switch (building.material) {
    case BuildingMaterial::Brick:
    case BuildingMaterial::Stone:
    case BuildingMaterial::Sandstone: s.reveal = 0.25f; break;
    case BuildingMaterial::Wood:
    case BuildingMaterial::Timber: s.reveal = 0.12f; break;
    default: break;
    }
    return s;
}

} // namespace urbis
