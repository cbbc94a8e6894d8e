// SampledTensorField::EmitGlsl: the sampled metric's spline in GLSL, read
// from two 3D float textures in one of two ways (GlslEmitOptions):
// - texel reads: the 64 texels around the cell, read with texelFetch and
//   weighted in the shader in float, the CPU's spline to float rounding;
// - filtered reads: the same sums from 8 trilinear reads each, the texture
//   unit doing the weighting (Sigg and Hadwiger, GPU Gems 2, ch. 20).
// Both are straight-line code: with the 4 x 4 x 4 sum as nested loops, Mesa's
// llvmpipe ended rays of more than a few hundred RK4 steps early (the same
// shader with fewer steps matched the CPU), consistent with its loop limiter
// counting every inner iteration of the invocation.
#include "SampledTensorField.h"

#include "GlslSource.h"

#include <mutex>
#include <string>

namespace riemann
{
namespace
{
/// The names the spline's code refers to.
struct SplineNames
{
  std::string Diagonal;    // sampler3D of (XX, YY, ZZ)
  std::string OffDiagonal; // sampler3D of (XY, YZ, XZ)
  std::string Origin;      // vec3 grid origin
  std::string ToGrid;      // mat3 W: u = W (p - origin)
  std::string LastIndex;   // vec3 (n - 1) per axis
  std::string Margin;      // the box beyond the outer samples: SampledTensorField::FaceMargin
  bool StopOutside = false;
};

/// The symmetric matrix of diagonal d (XX, YY, ZZ) and off-diagonal o (XY, YZ, XZ).
std::string Symmetric(const std::string& d, const std::string& o)
{
  return "mat3(" + d + ".x, " + o + ".x, " + o + ".z, " + o + ".x, " + d + ".y, " + o + ".y, " + o +
    ".z, " + o + ".y, " + d + ".z)";
}

/**
 * The spline function's start: u, the grid coordinates of p, clamped to the
 * box, and `continued` per axis beyond a face. "euclidean": g = I outside the
 * box, without reading a texel (rays spend most of their steps outside a
 * small volume).
 */
std::string Prologue(const SplineNames& names)
{
  std::string code = "  vec3 u = " + names.ToGrid + " * (p - " + names.Origin +
    ");\n"
    "  // Beyond a face: the face's value, constant along that axis.\n"
    "  vec3 inBox = clamp(u, vec3(-" +
    names.Margin + "), " + names.LastIndex + " + " + names.Margin +
    ");\n"
    "  bvec3 continued = notEqual(u, inBox);\n";
  if (!names.StopOutside)
  {
    code += "  if (any(continued))\n"
            "  {\n"
            "    g = mat3(1.0);\n"
            "    dg0 = mat3(0.0);\n"
            "    dg1 = mat3(0.0);\n"
            "    dg2 = mat3(0.0);\n"
            "    return;\n"
            "  }\n";
  }
  return code + "  u = inBox;\n";
}

/**
 * The spline function's end: g from the sums (d, o), its grid derivatives
 * from (dx, ox), (dy, oy), (dz, oz), and the chain rule of Evaluate() to
 * world derivatives.
 */
std::string Epilogue(const SplineNames& names)
{
  const std::string& W = names.ToGrid;
  return "  g = " + Symmetric("d", "o") +
    ";\n"
    "  mat3 gu[3];\n"
    "  gu[0] = " +
    Symmetric("dx", "ox") + ";\n  gu[1] = " + Symmetric("dy", "oy") +
    ";\n  gu[2] = " + Symmetric("dz", "oz") + ";\n  // d/dp_k = sum_a W(a, k) d/du_a; W(a, k) is " +
    W +
    "[k][a].\n"
    "  dg0 = " +
    W + "[0][0] * gu[0] + " + W + "[0][1] * gu[1] + " + W + "[0][2] * gu[2];\n  dg1 = " + W +
    "[1][0] * gu[0] + " + W + "[1][1] * gu[1] + " + W + "[1][2] * gu[2];\n  dg2 = " + W +
    "[2][0] * gu[0] + " + W + "[2][1] * gu[1] + " + W + "[2][2] * gu[2];\n";
}

/// The uniform cubic B-spline's weights w0..w3 of the samples cell - 1 ..
/// cell + 2 at fraction t of the cell, and their derivatives d0..d3 in t.
const char* const SplineWeights = "  float s = 1.0 - t;\n"
                                  "  float t2 = t * t;\n"
                                  "  float t3 = t2 * t;\n"
                                  "  float w0 = s * s * s / 6.0;\n"
                                  "  float w1 = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;\n"
                                  "  float w2 = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;\n"
                                  "  float w3 = t3 / 6.0;\n"
                                  "  float d0 = -0.5 * s * s;\n"
                                  "  float d1 = 1.5 * t2 - 2.0 * t;\n"
                                  "  float d2 = -1.5 * t2 + t + 0.5;\n"
                                  "  float d3 = 0.5 * t2;\n";

const char* const SplineSignature =
  "(vec3 p, out mat3 g, out mat3 dg0, out mat3 dg1, out mat3 dg2)";

/// The spline from the 64 texels, weighted in the shader (EvaluateInGrid, order 1).
std::string EmitTexelSpline(GlslBuilder& builder, const SplineNames& names)
{
  const std::string weights = builder.NewName("bspline_weights");
  builder.AddFunction("void " + weights +
    "(float t, bool continued, out float w[4], out float dw[4])\n"
    "{\n" +
    std::string(SplineWeights) +
    "  w[0] = w0;\n"
    "  w[1] = w1;\n"
    "  w[2] = w2;\n"
    "  w[3] = w3;\n"
    "  // Constant along an axis beyond the faces (\"outside\": \"stop\").\n"
    "  float k = continued ? 0.0 : 1.0;\n"
    "  dw[0] = k * d0;\n"
    "  dw[1] = k * d1;\n"
    "  dw[2] = k * d2;\n"
    "  dw[3] = k * d3;\n"
    "}\n");
  // One row of four samples along x. sums: value and x, y, z grid
  // derivatives of the diagonal and off-diagonal components.
  const std::string row = builder.NewName("sampled_row");
  std::string rowCode = "void " + row +
    "(int i0, int lastX, int jj, int kk, float wx[4], float dwx[4], float wyz, float dyz, "
    "float ydz, inout vec3 sums[8])\n"
    "{\n";
  for (int a = 0; a < 4; ++a)
  {
    const std::string n = std::to_string(a);
    rowCode += "  {\n    ivec3 index = ivec3(clamp(i0 + " + n +
      ", 0, lastX), jj, kk);\n    vec3 sd = texelFetch(" + names.Diagonal +
      ", index, 0).rgb;\n    vec3 so = texelFetch(" + names.OffDiagonal +
      ", index, 0).rgb;\n    float w = wx[" + n + "] * wyz;\n    float wdx = dwx[" + n +
      "] * wyz;\n    float wdy = wx[" + n + "] * dyz;\n    float wdz = wx[" + n +
      "] * ydz;\n"
      "    sums[0] += w * sd;\n"
      "    sums[1] += w * so;\n"
      "    sums[2] += wdx * sd;\n"
      "    sums[3] += wdx * so;\n"
      "    sums[4] += wdy * sd;\n"
      "    sums[5] += wdy * so;\n"
      "    sums[6] += wdz * sd;\n"
      "    sums[7] += wdz * so;\n"
      "  }\n";
  }
  builder.AddFunction(rowCode + "}\n");

  std::string rows;
  for (int c = 0; c < 4; ++c)
  {
    for (int b = 0; b < 4; ++b)
    {
      const std::string sb = std::to_string(b);
      const std::string sc = std::to_string(c);
      rows += "  " + row + "(cell.x - 1, last.x, clamp(cell.y + " + std::to_string(b - 1) +
        ", 0, last.y), clamp(cell.z + " + std::to_string(c - 1) + ", 0, last.z), wx, dwx, wy[" +
        sb + "] * wz[" + sc + "], dwy[" + sb + "] * wz[" + sc + "], wy[" + sb + "] * dwz[" + sc +
        "], sums);\n";
    }
  }
  const std::string name = builder.NewName("sampled_tensor");
  builder.AddFunction("void " + name + SplineSignature + "\n{\n" + Prologue(names) +
    "  ivec3 last = ivec3(" + names.LastIndex +
    " + 0.5);\n"
    "  ivec3 cell = min(ivec3(floor(u)), last);\n"
    "  vec3 t = u - vec3(cell);\n"
    "  float wx[4], wy[4], wz[4], dwx[4], dwy[4], dwz[4];\n  " +
    weights + "(t.x, continued.x, wx, dwx);\n  " + weights + "(t.y, continued.y, wy, dwy);\n  " +
    weights +
    "(t.z, continued.z, wz, dwz);\n"
    "  vec3 sums[8] = vec3[8](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), "
    "vec3(0.0), vec3(0.0), vec3(0.0));\n" +
    rows +
    "  vec3 d = sums[0], o = sums[1], dx = sums[2], ox = sums[3];\n"
    "  vec3 dy = sums[4], oy = sums[5], dz = sums[6], oz = sums[7];\n" +
    Epilogue(names) + "}\n");
  return name;
}

/**
 * The spline from trilinear reads. Along an axis the value's four weights,
 * and the derivative's, come in two pairs of one sign; a pair is one linear
 * read at the weighted position between its two texels. So a sum over
 * 4 x 4 x 4 texels is 8 trilinear reads, and the value with the three grid
 * derivatives 32 per texture. A texel index clamps to the grid as on the
 * CPU (the textures clamp to their edges).
 */
std::string EmitFilteredSpline(GlslBuilder& builder, const SplineNames& names)
{
  const std::string axis = builder.NewName("bspline_axis");
  builder.AddFunction("void " + axis +
    "(float u, float cell, float n, bool continued, out vec2 g, out vec2 c, out vec2 gd, "
    "out vec2 cd)\n"
    "{\n"
    "  float t = u - cell;\n" +
    std::string(SplineWeights) +
    "  // (w0, w1) weigh texels cell - 1 and cell, (w2, w3) cell + 1 and cell + 2;\n"
    "  // c: the read positions in texture coordinates, (index + 1/2) / n.\n"
    "  g = vec2(w0 + w1, w2 + w3);\n"
    "  c = (vec2(cell - 1.0 + w1 / g.x, cell + 1.0 + w3 / g.y) + 0.5) / n;\n"
    "  // The derivative's: d0, d1 <= 0 <= d2, d3, each pair's sum at least 1/2 from 0.\n"
    "  // Constant along an axis beyond the faces (\"outside\": \"stop\").\n"
    "  gd = (continued ? 0.0 : 1.0) * vec2(d0 + d1, d2 + d3);\n"
    "  cd = (vec2(cell - 1.0 + d1 / (d0 + d1), cell + 1.0 + d3 / (d2 + d3)) + 0.5) / n;\n"
    "}\n");
  const std::string reads = builder.NewName("sampled_reads");
  std::string readsCode = "void " + reads +
    "(vec2 gx, vec2 cx, vec2 gy, vec2 cy, vec2 gz, vec2 cz, out vec3 d, out vec3 o)\n"
    "{\n"
    "  vec3 p;\n"
    "  float w;\n"
    "  d = vec3(0.0);\n"
    "  o = vec3(0.0);\n";
  for (int corner = 0; corner < 8; ++corner)
  {
    const std::string a = (corner & 1) ? "y" : "x";
    const std::string b = (corner & 2) ? "y" : "x";
    const std::string c = (corner & 4) ? "y" : "x";
    readsCode += "  p = vec3(cx." + a + ", cy." + b + ", cz." + c + ");\n  w = gx." + a + " * gy." +
      b + " * gz." + c + ";\n  d += w * texture(" + names.Diagonal +
      ", p).rgb;\n  o += w * texture(" + names.OffDiagonal + ", p).rgb;\n";
  }
  builder.AddFunction(readsCode + "}\n");

  const std::string name = builder.NewName("sampled_tensor");
  builder.AddFunction("void " + name + SplineSignature + "\n{\n" + Prologue(names) +
    "  vec3 cell = min(floor(u), " + names.LastIndex + ");\n  vec3 n = " + names.LastIndex +
    " + 1.0;\n"
    "  vec2 gx, cx, gdx, cdx, gy, cy, gdy, cdy, gz, cz, gdz, cdz;\n  " +
    axis + "(u.x, cell.x, n.x, continued.x, gx, cx, gdx, cdx);\n  " + axis +
    "(u.y, cell.y, n.y, continued.y, gy, cy, gdy, cdy);\n  " + axis +
    "(u.z, cell.z, n.z, continued.z, gz, cz, gdz, cdz);\n"
    "  vec3 d, o, dx, ox, dy, oy, dz, oz;\n  " +
    reads + "(gx, cx, gy, cy, gz, cz, d, o);\n  " + reads +
    "(gdx, cdx, gy, cy, gz, cz, dx, ox);\n  " + reads + "(gx, cx, gdy, cdy, gz, cz, dy, oy);\n  " +
    reads + "(gx, cx, gy, cy, gdz, cdz, dz, oz);\n" + Epilogue(names) + "}\n");
  return name;
}
} // namespace

std::string SampledTensorField::EmitGlsl(GlslBuilder& builder) const
{
  // Step 1: the samples as two float textures, once per field.
  std::call_once(this->TexelsMade,
    [this]()
    {
      const std::size_t n = static_cast<std::size_t>(this->Grid.NumberOfPoints());
      auto diagonal = std::make_shared<std::vector<float>>(3 * n);
      auto offDiagonal = std::make_shared<std::vector<float>>(3 * n);
      const double* c = this->Grid.Components.data();
      for (std::size_t i = 0; i < n; ++i)
      {
        for (int m = 0; m < 3; ++m)
        {
          (*diagonal)[3 * i + m] = static_cast<float>(c[6 * i + m]);
          (*offDiagonal)[3 * i + m] = static_cast<float>(c[6 * i + 3 + m]);
        }
      }
      this->DiagonalTexels = diagonal;
      this->OffDiagonalTexels = offDiagonal;
    });
  SplineNames names;
  GlslTexture3D texture;
  texture.Dimensions = this->Grid.Dimensions;
  texture.Components = 3;
  texture.Values = this->DiagonalTexels;
  names.Diagonal = builder.AddTexture3D("tensor_diagonal", texture);
  texture.Values = this->OffDiagonalTexels;
  names.OffDiagonal = builder.AddTexture3D("tensor_off_diagonal", texture);

  // Step 2: the grid's geometry as uniforms: u = W (p - origin), the box
  // u in [-1/2, n - 1/2] (to the outer voxels' faces).
  const Vec3 last(
    this->Grid.Dimensions[0] - 1.0, this->Grid.Dimensions[1] - 1.0, this->Grid.Dimensions[2] - 1.0);
  names.Origin = builder.AddUniform("grid_origin", "vec3",
    std::vector<double>(this->Grid.Origin.data(), this->Grid.Origin.data() + 3));
  names.ToGrid = builder.AddUniform("world_to_grid", "mat3",
    std::vector<double>(this->WorldToGrid.data(), this->WorldToGrid.data() + 9));
  names.LastIndex =
    builder.AddUniform("grid_last", "vec3", std::vector<double>(last.data(), last.data() + 3));
  names.StopOutside = this->StopOutside;
  static_assert(FaceMargin == 0.5, "the shader's box is the CPU's");
  names.Margin = "0.5";

  // Step 3: where the data holds (only asked for when rays stop outside).
  if (this->StopOutside)
  {
    const std::string inside = builder.NewName("sampled_inside");
    builder.AddFunction("bool " + inside + "(vec3 p)\n{\n  vec3 u = " + names.ToGrid + " * (p - " +
      names.Origin + ");\n  return all(greaterThanEqual(u, vec3(-" + names.Margin +
      "))) && all(lessThanEqual(u, " + names.LastIndex + " + " + names.Margin + "));\n}\n");
    builder.SetInsideDataFunction(inside);
  }

  // Step 4: the spline, read as the renderer asks.
  return builder.GetOptions().FilteredTextureReads ? EmitFilteredSpline(builder, names)
                                                   : EmitTexelSpline(builder, names);
}
} // namespace riemann
