// VoxelChristoffelMetric::EmitGlsl: the voxels' g and dg in GLSL, read
// with the texture unit's trilinear filtering (the interactive reading of
// sampled metrics). The 24 numbers of a voxel lie in six RGBA float 3D
// textures, four each, in the CPU's order (g: XX YY ZZ XY YZ XZ, then d_0 g,
// d_1 g, d_2 g in the same order), so one evaluation is six filtered reads
// at the same texture coordinate, where the spline's is 64 texel reads of
// two textures (or 32 filtered reads), then the tensor family's formula.
#include "VoxelChristoffelMetric.h"

#include "GlslSource.h"
#include "TensorMetric.h"

#include <string>

namespace riemann
{
namespace
{
constexpr int Values = 24;
constexpr int TexelComponents = 4;
constexpr int Textures = Values / TexelComponents;

/// The symmetric matrix of the six values XX, YY, ZZ, XY, YZ, XZ (GLSL expressions).
std::string Symmetric(const std::string (&c)[6])
{
  return "mat3(" + c[0] + ", " + c[3] + ", " + c[5] + ", " + c[3] + ", " + c[1] + ", " + c[4] +
    ", " + c[5] + ", " + c[4] + ", " + c[2] + ")";
}
} // namespace

void VoxelChristoffelMetric::MakeTexels() const
{
  std::call_once(this->TexelsMade,
    [this]()
    {
      const std::size_t voxels = this->Samples.size() / Values;
      for (int t = 0; t < Textures; ++t)
      {
        auto texels = std::make_shared<std::vector<float>>(TexelComponents * voxels);
        for (std::size_t v = 0; v < voxels; ++v)
        {
          for (int c = 0; c < TexelComponents; ++c)
          {
            (*texels)[TexelComponents * v + c] =
              this->Samples[Values * v + TexelComponents * t + c];
          }
        }
        this->Texels[t] = texels;
      }
    });
}

void VoxelChristoffelMetric::EmitGlsl(GlslBuilder& builder) const
{
  // Step 1: beyond the box, the wrapped metric's field: g = I, or with
  // "outside": "stop" the spline's continuation (which also names the
  // inside-data test), as Christoffel() and Tensor() fall back on the CPU.
  const bool stopOutside = this->Field->GetStopOutside();
  const std::string beyond = stopOutside ? this->Field->EmitGlsl(builder) : std::string();

  // Step 2: the voxels' numbers as six RGBA float textures, once per metric.
  this->MakeTexels();
  std::string texture[Textures];
  for (int t = 0; t < Textures; ++t)
  {
    GlslTexture3D volume;
    volume.Dimensions = this->Geometry.Dimensions;
    volume.Components = TexelComponents;
    volume.Values = this->Texels[t];
    texture[t] = builder.AddTexture3D("voxel_jet", volume);
  }

  // Step 3: the grid's placement: u = W (p - origin), the box u in
  // [-1/2, n - 1/2] (SampledTensorField::WithinFaces, to the outer faces).
  const std::array<int, 3>& n = this->Geometry.Dimensions;
  const Vec3 last(n[0] - 1.0, n[1] - 1.0, n[2] - 1.0);
  const std::string origin = builder.AddUniform("voxel_origin", "vec3",
    std::vector<double>(this->Geometry.Origin.data(), this->Geometry.Origin.data() + 3));
  const std::string toGrid = builder.AddUniform("voxel_to_grid", "mat3",
    std::vector<double>(this->WorldToGrid.data(), this->WorldToGrid.data() + 9));
  const std::string lastIndex =
    builder.AddUniform("voxel_last", "vec3", std::vector<double>(last.data(), last.data() + 3));
  static_assert(SampledTensorField::FaceMargin == 0.5, "the shader's box is the CPU's");

  // Step 4: the reading. Between an outer voxel and its face the texture
  // coordinate is clamped to that voxel's centre, as Interpolate() clamps.
  std::string code = "  vec3 u = " + toGrid + " * (p - " + origin +
    ");\n"
    "  if (any(notEqual(u, clamp(u, vec3(-0.5), " +
    lastIndex + " + 0.5))))\n  {\n";
  code += stopOutside ? "    " + beyond + "(p, g, dg0, dg1, dg2);\n"
                      : std::string("    g = mat3(1.0);\n"
                                    "    dg0 = mat3(0.0);\n"
                                    "    dg1 = mat3(0.0);\n"
                                    "    dg2 = mat3(0.0);\n");
  code += "    return;\n  }\n  vec3 c = (clamp(u, vec3(0.0), " + lastIndex + ") + 0.5) / (" +
    lastIndex + " + 1.0);\n";
  for (int t = 0; t < Textures; ++t)
  {
    code += "  vec4 r" + std::to_string(t) + " = texture(" + texture[t] + ", c);\n";
  }
  // Value v of the 24 is component v % 4 of read v / 4.
  const auto value = [](int v) { return "r" + std::to_string(v / 4) + "." + "xyzw"[v % 4]; };
  const char* const outputs[4] = { "g", "dg0", "dg1", "dg2" };
  for (int m = 0; m < 4; ++m)
  {
    std::string c[6];
    for (int q = 0; q < 6; ++q)
    {
      c[q] = value(6 * m + q);
    }
    code += std::string("  ") + outputs[m] + " = " + Symmetric(c) + ";\n";
  }
  const std::string name = builder.NewName("voxel_tensor");
  builder.AddFunction("void " + name +
    "(vec3 p, out mat3 g, out mat3 dg0, out mat3 dg1, out mat3 dg2)\n{\n" + code + "}\n");

  // Step 5: the symbols of the read g and dg, the tensor family's formula.
  EmitTensorMetricGlsl(builder, name);
}
} // namespace riemann
