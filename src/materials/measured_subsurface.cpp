#include "materials/measured_subsurface.h"

#include <iterator>

namespace candela {

namespace {

struct NamedMedium {
  const char* name;
  MeasuredSubsurface medium;
};

// sigma_s' then sigma_a, each (R, G, B) in mm^-1. Jensen et al. 2001, Table 1:
const NamedMedium kMedia[] = {
    {"Apple", {{2.29f, 2.39f, 1.97f}, {0.0030f, 0.0034f, 0.046f}}},
    {"Chicken1", {{0.15f, 0.21f, 0.38f}, {0.015f, 0.077f, 0.19f}}},
    {"Chicken2", {{0.19f, 0.25f, 0.32f}, {0.018f, 0.088f, 0.20f}}},
    {"Cream", {{7.38f, 5.47f, 3.15f}, {0.0002f, 0.0028f, 0.0163f}}},
    {"Ketchup", {{0.18f, 0.07f, 0.03f}, {0.061f, 0.97f, 1.45f}}},
    {"Marble", {{2.19f, 2.62f, 3.00f}, {0.0021f, 0.0041f, 0.0071f}}},
    {"Potato", {{0.68f, 0.70f, 0.55f}, {0.0024f, 0.0090f, 0.12f}}},
    {"Skimmilk", {{0.70f, 1.22f, 1.90f}, {0.0014f, 0.0025f, 0.0142f}}},
    {"Skin1", {{0.74f, 0.88f, 1.01f}, {0.032f, 0.17f, 0.48f}}},
    {"Skin2", {{1.09f, 1.59f, 1.79f}, {0.013f, 0.070f, 0.145f}}},
    {"Spectralon", {{11.6f, 20.4f, 14.9f}, {0.00f, 0.00f, 0.00f}}},
    {"Wholemilk", {{2.55f, 3.21f, 3.77f}, {0.0011f, 0.0024f, 0.014f}}},
    // Narasimhan, Gupta, Donner, Ramamoorthi, Nayar and Jensen 2006, "Acquiring Scattering
    // Properties of Participating Media by Dilution", as pbrt-v2 tabulates them (same order and
    // units). pbrt-v3 later re-derived these media's coefficients from the paper, so its values
    // differ; these render as pbrt-v2 renders them.
    {"Lowfat Milk", {{0.9126f, 1.0748f, 1.25f}, {0.0002f, 0.0004f, 0.0008f}}},
    {"Reduced Milk", {{1.075f, 1.2213f, 1.3941f}, {0.0002f, 0.0004f, 0.001f}}},
    {"Regular Milk", {{1.1874f, 1.3296f, 1.4602f}, {0.0001f, 0.0003f, 0.0013f}}},
    {"Espresso", {{0.4376f, 0.5115f, 0.6048f}, {0.1669f, 0.2287f, 0.3078f}}},
    {"Mint Mocha Coffee", {{0.19f, 0.26f, 0.35f}, {0.0984f, 0.1519f, 0.204f}}},
    {"Lowfat Soy Milk", {{0.1419f, 0.1625f, 0.274f}, {0.0001f, 0.0005f, 0.0025f}}},
    {"Regular Soy Milk", {{0.2434f, 0.2719f, 0.4597f}, {0.0001f, 0.0005f, 0.0034f}}},
    {"Lowfat Chocolate Milk", {{0.4282f, 0.5014f, 0.5791f}, {0.0005f, 0.0016f, 0.0068f}}},
    {"Regular Chocolate Milk", {{0.7359f, 0.9172f, 1.0688f}, {0.0007f, 0.003f, 0.01f}}},
    {"Coke", {{0.7143f, 1.1688f, 1.7169f}, {0.6966f, 1.148f, 1.7169f}}},
    {"Pepsi", {{0.6433f, 0.999f, 1.442f}, {0.6375f, 0.9849f, 1.442f}}},
    {"Sprite", {{0.1299f, 0.1283f, 0.1395f}, {0.123f, 0.1194f, 0.1306f}}},
    {"Gatorade", {{0.4009f, 0.4185f, 0.4324f}, {0.1617f, 0.1258f, 0.0579f}}},
    {"Chardonnay", {{0.1577f, 0.1748f, 0.3512f}, {0.1547f, 0.1701f, 0.3443f}}},
    {"White Zinfandel", {{0.1763f, 0.237f, 0.2913f}, {0.1732f, 0.2322f, 0.2847f}}},
    {"Merlot", {{0.7639f, 1.6429f, 1.9196f}, {0.7586f, 1.6429f, 1.9196f}}},
    {"Budweiser Beer", {{0.1486f, 0.321f, 0.736f}, {0.1449f, 0.3141f, 0.7286f}}},
    {"Coors Light Beer", {{0.0295f, 0.0663f, 0.1521f}, {0.0268f, 0.0608f, 0.1521f}}},
    {"Clorox", {{0.16f, 0.25f, 0.33f}, {0.0175f, 0.0777f, 0.1372f}}},
    {"Apple Juice", {{0.1215f, 0.2101f, 0.4407f}, {0.1014f, 0.1858f, 0.4084f}}},
    {"Cranberry Juice", {{0.27f, 0.63f, 0.83f}, {0.2572f, 0.6145f, 0.8104f}}},
    {"Grape Juice", {{0.55f, 1.25f, 1.53f}, {0.5428f, 1.25f, 1.53f}}},
    {"Ruby Grapefruit Juice", {{0.2513f, 0.3517f, 0.4305f}, {0.0896f, 0.1911f, 0.2636f}}},
    {"White Grapefruit Juice", {{0.3609f, 0.38f, 0.5632f}, {0.0096f, 0.0131f, 0.0395f}}},
    {"Shampoo", {{0.0288f, 0.071f, 0.0952f}, {0.0184f, 0.0596f, 0.0805f}}},
    {"Strawberry Shampoo", {{0.0217f, 0.0788f, 0.1022f}, {0.0189f, 0.0756f, 0.0989f}}},
    {"Head & Shoulders Shampoo", {{0.3674f, 0.4527f, 0.5211f}, {0.0883f, 0.1637f, 0.2125f}}},
    {"Lemon Tea", {{0.34f, 0.58f, 0.88f}, {0.2602f, 0.4902f, 0.7727f}}},
    {"Orange Juice Powder", {{0.3377f, 0.5573f, 1.0122f}, {0.1449f, 0.3441f, 0.7863f}}},
    {"Pink Lemonade", {{0.24f, 0.37f, 0.45f}, {0.1165f, 0.2366f, 0.3195f}}},
    {"Cappuccino Powder", {{0.2574f, 0.3536f, 0.484f}, {0.192f, 0.2654f, 0.3272f}}},
    {"Salt Powder", {{0.76f, 0.8685f, 0.9363f}, {0.5115f, 0.5863f, 0.6147f}}},
    {"Sugar Powder", {{0.0795f, 0.1759f, 0.278f}, {0.065f, 0.1597f, 0.2578f}}},
    {"Suisse Mocha", {{0.5098f, 0.6476f, 0.7944f}, {0.1875f, 0.2893f, 0.3796f}}},
    {"Pacific Ocean Surface Water", {{3.3645f, 3.3158f, 3.2428f}, {3.1845f, 3.1324f, 3.0147f}}},
};

}  // namespace

std::optional<MeasuredSubsurface> measuredSubsurface(const std::string& name) {
  for (const NamedMedium& m : kMedia)
    if (name == m.name) return m.medium;
  return std::nullopt;
}

std::vector<std::string> measuredSubsurfaceNames() {
  std::vector<std::string> names;
  names.reserve(std::size(kMedia));
  for (const NamedMedium& m : kMedia) names.emplace_back(m.name);
  return names;
}

}  // namespace candela
