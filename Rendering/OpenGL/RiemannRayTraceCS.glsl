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
//   RT_GROUP_X, RT_GROUP_Y  the tile of pixels of one workgroup, one
//                           workgroup per tile
//   RT_GROUP_INVOCATIONS    RT_GROUP_X * RT_GROUP_Y, as a literal (GLSL 4.30
//                           takes no expression in a layout qualifier)
// (A persistent-thread queue, invocations taking pixels from an atomic
// counter, was tried: Mesa llvmpipe 22.3 drew wrong pixels whenever an
// invocation traced a second ray, so it is not kept; README, "The compute
// path".)
// ---------------------------------------------------------------------------

//RT::Constants::Dec

//RT::Metric::Impl

//RT::Meshes::Impl

//RT::Scene::Impl

//RT::Integrators::Impl

//RT::Extra::Impl

//RT::Pixel::Impl

// One workgroup per tile of RT_GROUP_X x RT_GROUP_Y pixels, its invocations
// numbered in one dimension so that each run of 8 consecutive invocations
// (a SIMD vector of llvmpipe, a quarter of an NVIDIA warp) covers a 4 x 2
// block of pixels, as a fragment shader's quads do, rather than a row of 8:
// neighbouring rays bend alike and read the same texels. Measured on
// llvmpipe: the sampled lens 1.20 times the fragment path's time with rows
// of 8, the same time with blocks.
layout(local_size_x = RT_GROUP_INVOCATIONS, local_size_y = 1, local_size_z = 1) in;

// The workgroups of a dispatch (tiles across, tiles down) and the stride
// that scatters them: workgroup n (in dispatch order) traces tile n *
// rt_tile_stride mod count, so that any contiguous share of the workgroups
// (what one thread of a CPU renderer may take) has tiles from all over the
// image. Rays differ in length (a floor is hit in a few steps, the sky takes
// all of them): in tile order, Mesa llvmpipe left a thread idle while the
// other traced the sky, and the showcase lens took 1.37 times the fragment
// path's time.
uniform ivec2 rt_tile_grid;
uniform int rt_tile_stride;

// The cell (pixel or lattice point) of this invocation.
ivec2 rt_invocation_cell()
{
  int index = int(gl_LocalInvocationIndex);
  ivec2 local;
#if RT_GROUP_X % 4 == 0 && RT_GROUP_Y % 2 == 0
  int block = index / 8;
  int lane = index - 8 * block;
  int blocksPerRow = RT_GROUP_X / 4;
  local = ivec2((block % blocksPerRow) * 4 + lane % 4, (block / blocksPerRow) * 2 + lane / 4);
#else
  local = ivec2(index % RT_GROUP_X, index / RT_GROUP_X);
#endif
  uint count = uint(rt_tile_grid.x * rt_tile_grid.y);
  uint order = gl_WorkGroupID.y * uint(rt_tile_grid.x) + gl_WorkGroupID.x;
  uint tile = (order * uint(rt_tile_stride)) % count;
  ivec2 origin = ivec2(int(tile % uint(rt_tile_grid.x)), int(tile / uint(rt_tile_grid.x)));
  return origin * ivec2(RT_GROUP_X, RT_GROUP_Y) + local;
}

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
  ivec2 cell = rt_invocation_cell();
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
