// Fixed-point formats of the Watkins pipeline: the one source of every width and fraction.
// rtl/watkins_pkg.sv is generated from this list by `watkins_gen_pkg` (tests/test_formats.cpp
// fails when the committed package and this header differ), so C++ and SystemVerilog agree.
//
// Every interpolated quantity is a *channel*: X (pixels), Z (depth), and R, G, B (8-bit levels)
// for Gouraud shading or Nx, Ny, Nz (the vertex normal, |N| = 1) for Phong shading, in the same
// slots: Phong takes the colour from the polygon's material, so both carry five channels. A
// channel value and its slope are signed two's complement words of ChannelBits bits with
// FracBits fraction bits, one format for all, so one incrementer and one interpolator
// serve every channel. The integer part each channel needs is listed beside it.
#pragma once

// X(name, value, comment). Order matters only for the generated package's readability.
#define WATKINS_FORMATS(X)                                                                       \
  X(ScreenBits, 12, "screen width and height <= 2^ScreenBits pixels (4096)")                     \
  X(LineBits, 13, "scan-line index and edge line count, 0..2^ScreenBits inclusive")              \
  X(SubPixelBits, 4, "vertex X, Y fraction bits: 1/16 pixel")                                    \
  X(VertexIntBits, 14, "vertex X, Y signed integer bits: guard band [-8192, 8192) pixels")       \
  X(FracBits, 16, "fraction bits of every channel value and slope")                              \
  X(ChannelBits, 42, "signed word of every channel value and slope")                             \
  X(DepthBits, 24, "depth integer part: depth in [0,1) maps to [0, 2^DepthBits)")                \
  X(ShadeBits, 8, "shade integer part: 8-bit levels 0..255")                                     \
  X(NumChannels, 5, "channels per edge record: X, Z, then R, G, B (Gouraud) or Nx, Ny, Nz (Phong)") \
  X(ChanX, 0, "channel index of X")                                                              \
  X(ChanZ, 1, "channel index of depth")                                                          \
  X(ChanR, 2, "channel index of red")                                                            \
  X(ChanG, 3, "channel index of green")                                                          \
  X(ChanB, 4, "channel index of blue")                                                           \
  X(ChanNx, 2, "phong: channel index of the normal's x (the slot of red)")                       \
  X(ChanNy, 3, "phong: channel index of the normal's y")                                         \
  X(ChanNz, 4, "phong: channel index of the normal's z")                                         \
  X(RecipBits, 24, "span reciprocal: mantissa bits of 1/(X_F - X_E), relative error < 2^-23")    \
  X(AlphaBits, 24, "fraction bits of the prestep coefficient alpha0 = (x_c - X_E)/(X_F - X_E)")  \
  X(Eq2RecipBits, 16, "eq. (2) shade divider: mantissa bits of 1/depth, relative error < 2^-(Eq2RecipBits-1)") \
  X(PolyIdBits, 16, "polygon id bits: at most 65536 polygons per frame")                         \
  X(EdgeIdBits, 18, "edge id bits: position of a record in the frame's edge stream (262144 records)")   \
  X(MaxActiveEdges, 64, "default capacity of the active-edge list")                              \
  X(DefaultMaxWidth, 1024, "default line-buffer width of watkins_top in pixels (MaxWidth)")      \
  X(NormalInBits, 18, "normalizer input: interpolated Nx, Ny, Nz, signed, FracBits fraction bits")  \
  X(UnitBits, 16, "unit normal component out of the normalizer: signed Q2.14")                   \
  X(UnitFracBits, 14, "fraction bits of a unit normal component (1.0 = 16384)")             \
  X(RsqrtMantBits, 20, "normalizer: bits of m' in [1/4,1) fed to 1/sqrt (low bits truncated)")   \
  X(RsqrtIndexBits, 10, "normalizer: top bits of m' indexing the 1/sqrt seed table (768 rows)")  \
  X(RsqrtSeedBits, 14, "normalizer: fraction bits of the seed y0 ~ 1/sqrt(m') in [1,2)")         \
  X(RsqrtNrBits, 24, "normalizer: fraction bits of m'*y0^2 in the Newton-Raphson step")          \
  X(RsqrtBits, 22, "normalizer: fraction bits of the refined y ~ 1/sqrt(m') in [1,2]")           \
  X(RsqrtStages, 10, "normalizer: rsqrt_unit's latency, one register stage per clock")             \
  X(PhongDotBits, 24, "phong: fraction bits of cos(i) = N.L, N.E and L.E")                       \
  X(PhongPowBits, 20, "phong: fraction bits of cos(s) and cos(s)^n, both in [0,1]")              \
  X(MaterialBits, 9, "phong: unsigned width of d and W (1.0 = 2^MaterialFracBits)")              \
  X(MaterialFracBits, 8, "phong: fraction bits of d and W")                                      \
  X(ShininessBits, 8, "phong: unsigned width of the specular exponent n (0..255)")              \
  X(MaterialIdBits, 4, "material id carried by every edge, segment and fragment (16 materials)") \
  X(SmoothWBits, 8, "smoother: unsigned width of Herman & Liu's weight W, in [0, 2)")            \
  X(SmoothWFracBits, 7, "smoother: fraction bits of W (1.0 = 128; W = 0 turns smoothing off)")

namespace watkins::fmt {
#define WATKINS_DECLARE_FORMAT(name, value, comment) constexpr int name = value;
WATKINS_FORMATS(WATKINS_DECLARE_FORMAT)
#undef WATKINS_DECLARE_FORMAT

// Derived values (also emitted into the package as localparams by the generator).
constexpr int MaxScreen = 1 << ScreenBits;
constexpr int ShadeMax = (1 << ShadeBits) - 1;
constexpr long long DepthMax = (1LL << DepthBits) - 1;  // "farthest" representable depth
constexpr int SubPixelToFrac = FracBits - SubPixelBits;  // shift from 1/16 pixel to X channel
constexpr int ShadeChannels = 3;                         // R, G, B after X and Z
constexpr int VertexLimit = 1 << (VertexIntBits - 1);    // vertex X, Y in [-VertexLimit, VertexLimit) pixels
constexpr int MaxPolygons = 1 << PolyIdBits;             // polygons per frame
constexpr int MaxMaterials = 1 << MaterialIdBits;        // Phong materials per frame
constexpr int MaxEdges = 1 << EdgeIdBits;                // edge records per frame (edge ids)
// $bits(watkins_pkg::edge_t): y0, n, poly, material, then value and slope of every channel.
constexpr int EdgeRecordBits = 2 * LineBits + PolyIdBits + MaterialIdBits + 2 * NumChannels * ChannelBits;
// The smoother's largest W (the scene's and the command line's range; C++ only).
constexpr double SmoothWMax = double((1 << SmoothWBits) - 1) / (1 << SmoothWFracBits);

static_assert(FracBits >= SubPixelBits, "X channel must hold the vertex sub-pixel bits");
static_assert(DepthBits + FracBits + 2 <= ChannelBits, "depth (plus sign and guard) must fit");
static_assert(VertexIntBits + FracBits + 1 <= ChannelBits, "X must fit a channel word");
static_assert(ChannelBits + RecipBits + 1 <= 127, "span products must fit 128-bit model math");
// W < 2 keeps the smoother's denominator d = 2^2F + 2^F·w·n_edge + w²·n_corner below
// 6.25·2^(2·SmoothWBits), so 2d fits rtl/smoother.sv's DivisorBits = 2·SmoothWBits + 4.
static_assert(SmoothWFracBits < SmoothWBits, "smoother: W must stay below 2 (its divider's width)");
}  // namespace watkins::fmt
