//RT::Version::Dec

// ---------------------------------------------------------------------------
// RiemannRayTraceCS.glsl: Riemannian ray tracing, one geodesic per compute
// invocation (vtkRiemannRayTracePass, GPUPath Compute; OpenGL 4.3). The tags
// are those of RiemannRayTraceFS.glsl, filled with the same GLSL, so a pixel
// is traced and shaded by the same rt_pixel() on both paths. Why a second
// path: on data-centre GPUs (NVIDIA's H100 and H200) only a few SMs run
// fragment shaders, while compute work is spread over all of them.
//
// Each invocation traces the pixel at its global id into images the pass
// then composes into VTK's framebuffer (RiemannReducedView): colour (RGBA8,
// image unit 0), window depth (R32F, unit 1), or with rt_output 1 the hit
// capture (RGBA32F, unit 2). Pixel (i, j) is the ray through
// (i + 1/2, j + 1/2) of the traced view, as gl_FragCoord on the fragment path.
//
// Compile-time constants added by the pass:
//   RT_GROUP_X, RT_GROUP_Y  the workgroup: one tile of pixels, one workgroup
//                           per tile. (A persistent-thread queue, invocations
//                           taking pixels from an atomic counter, was tried:
//                           Mesa llvmpipe 22.3 drew wrong pixels whenever an
//                           invocation traced a second ray, so it is not kept;
//                           README, "Compute path".)
// ---------------------------------------------------------------------------

//RT::Constants::Dec

//RT::Metric::Impl

//RT::Meshes::Impl

//RT::Scene::Impl

//RT::Integrators::Impl

//RT::Extra::Impl

//RT::Pixel::Impl

layout(local_size_x = RT_GROUP_X, local_size_y = RT_GROUP_Y, local_size_z = 1) in;

layout(binding = 0, rgba8) writeonly uniform image2D rt_color_image;
layout(binding = 1, r32f) writeonly uniform image2D rt_depth_image;
layout(binding = 2, rgba32f) writeonly uniform image2D rt_hit_image;

// The traced pixels (the images may be larger; the rest is left alone).
uniform ivec2 rt_traced_size;

void rt_trace_texel(ivec2 texel)
{
  if (texel.x >= rt_traced_size.x || texel.y >= rt_traced_size.y)
  {
    return;
  }
  vec4 color;
  float depth;
  rt_pixel(vec2(texel) + vec2(0.5) + rt_viewport.xy, color, depth);
  if (rt_output == 1)
  {
    imageStore(rt_hit_image, texel, color);
  }
  else
  {
    imageStore(rt_color_image, texel, color);
    imageStore(rt_depth_image, texel, vec4(depth, 0.0, 0.0, 0.0));
  }
}

// Progressive refinement (vtkRiemannRayTracePass::ProgressiveRefinement):
// the pixels of a lattice, every rt_lattice-th pixel from rt_lattice_origin,
// lattice point (i, j) at pixel rt_lattice_origin + (i, j) * rt_lattice.
// With rt_skip_coarse 0, invocation (i, j) traces point (i, j) for (i, j)
// below rt_lattice_size: a whole frame is lattice 1 from the origin. With
// rt_skip_coarse 1, only the points that the coarser lattice (every 2 *
// rt_lattice) has not traced, packed so that no invocation idles: rows go
// in pairs, invocation (x, p) of pair p < rt_lattice_size.y traces point
// (x, 2p + 1) for x below the rt_lattice_size.x columns, and the odd point
// (2 (x - columns) + 1, 2p) after them.
uniform int rt_lattice;
uniform ivec2 rt_lattice_origin;
uniform ivec2 rt_lattice_size;
uniform int rt_skip_coarse;

void main()
{
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  int columns = rt_lattice_size.x;
  ivec2 point = cell;
  if (rt_skip_coarse == 1)
  {
    if (cell.x >= columns + columns / 2 || cell.y >= rt_lattice_size.y)
    {
      return;
    }
    point = cell.x < columns ? ivec2(cell.x, 2 * cell.y + 1)
                             : ivec2(2 * (cell.x - columns) + 1, 2 * cell.y);
  }
  else if (cell.x >= columns || cell.y >= rt_lattice_size.y)
  {
    return;
  }
  rt_trace_texel(rt_lattice_origin + point * rt_lattice);
}
