/**
 * @file RiemannPlyCheck.h
 * @brief Private to Rendering/Scene: a PLY file checked against its own
 * header before VTK's reader sees it.
 *
 * VTK 9.1's vtkPLYReader trusts the file: a face whose vertex index is past
 * the vertices makes it read out of bounds (SIGSEGV), and a file that ends
 * before the elements its header declares makes it free memory twice
 * (SIGABRT). CheckPlyFile walks the body as the header describes it (ASCII
 * or binary, either byte order; scalar and list properties of every PLY
 * type) without building anything, and says what is wrong: a header that
 * does not parse, a body shorter than declared, a list with a negative or
 * absurd count, a face index outside the vertices. The walk costs one pass
 * over the file.
 */
#ifndef RiemannPlyCheck_h
#define RiemannPlyCheck_h

#include "RiemannRenderingSceneModule.h" // For export macro (tested on its own)

#include <string>

namespace riemann
{
/**
 * Check the PLY file at `path`: "" when its body is what its header
 * declares, else why not (without the path), e.g. "the file ends in element
 * face, row 7681 of 15360 (cut short?)" or "face 3 refers to vertex
 * 999999999, but there are 3 vertices".
 */
RIEMANNRENDERINGSCENE_EXPORT std::string CheckPlyFile(const std::string& path);
} // namespace riemann

#endif
