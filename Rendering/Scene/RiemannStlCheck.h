/**
 * @file RiemannStlCheck.h
 * @brief Private to Rendering/Scene: a binary STL file checked against its
 * own triangle count before VTK's reader sees it.
 *
 * A binary STL is an 80-byte header, a 32-bit triangle count n and n records
 * of 50 bytes. VTK 9.1's vtkSTLReader reads a binary file cut short without
 * a word: the triangles it did not find are simply missing. ASCII STL
 * (which VTK's reader checks line by line) passes here.
 */
#ifndef RiemannStlCheck_h
#define RiemannStlCheck_h

#include "RiemannRenderingSceneModule.h" // For export macro (tested on its own)

#include <string>

namespace riemann
{
/**
 * Check the STL file at `path`: "" when it is ASCII or a binary file of
 * exactly the size its triangle count declares, else why not (without the
 * path), e.g. "a binary STL of 448 triangles takes 22484 bytes, the file
 * has 5000 (cut short?)".
 */
RIEMANNRENDERINGSCENE_EXPORT std::string CheckStlFile(const std::string& path);
} // namespace riemann

#endif
