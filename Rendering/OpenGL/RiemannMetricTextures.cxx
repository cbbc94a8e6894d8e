#include "RiemannMetricTextures.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>

namespace riemann
{
bool MetricTextures::Update(
  const std::vector<GlslTexture3D>& textures, vtkOpenGLRenderWindow* window, std::string& error)
{
  std::vector<Uploaded> kept;
  for (const GlslTexture3D& wanted : textures)
  {
    // Step 1: the same data uploaded before (the volume did not change).
    auto same = std::find_if(this->Textures.begin(), this->Textures.end(),
      [&](const Uploaded& u) { return u.Values == wanted.Values && u.Texture; });
    if (same != this->Textures.end())
    {
      Uploaded reused = *same;
      reused.Uniform = wanted.Name;
      same->Texture = nullptr; // moved: not released below
      kept.push_back(reused);
      continue;
    }
    // Step 2: check the size the context allows, then upload.
    GLint largest = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
    const std::array<int, 3>& n = wanted.Dimensions;
    if (*std::max_element(n.begin(), n.end()) > largest)
    {
      error = "the sampled volume has " + std::to_string(n[0]) + "x" + std::to_string(n[1]) + "x" +
        std::to_string(n[2]) + " points; this OpenGL context's 3D textures hold at most " +
        std::to_string(largest) + " per axis (resample the volume, or render on the CPU)";
      return false;
    }
    if (!wanted.Values ||
      wanted.Values->size() !=
        static_cast<std::size_t>(n[0]) * n[1] * n[2] * static_cast<std::size_t>(wanted.Components))
    {
      error = "the metric's texture " + wanted.Name + " has the wrong number of values";
      return false;
    }
    Uploaded fresh;
    fresh.Uniform = wanted.Name;
    fresh.Values = wanted.Values;
    fresh.Texture = vtkSmartPointer<vtkTextureObject>::New();
    fresh.Texture->SetContext(window);
    fresh.Texture->SetWrapS(vtkTextureObject::ClampToEdge);
    fresh.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    fresh.Texture->SetWrapR(vtkTextureObject::ClampToEdge);
    // Linear for the spline's trilinear reads (FilteredTextureReads);
    // texelFetch, the other way, ignores the filter.
    fresh.Texture->SetMinificationFilter(vtkTextureObject::Linear);
    fresh.Texture->SetMagnificationFilter(vtkTextureObject::Linear);
    // Full float precision (32-bit texels, filtered by the texture unit).
    fresh.Texture->SetInternalFormat(wanted.Components == 4 ? GL_RGBA32F : GL_RGB32F);
    fresh.Texture->SetFormat(wanted.Components == 4 ? GL_RGBA : GL_RGB);
    fresh.Texture->SetDataType(GL_FLOAT);
    if (!fresh.Texture->Create3DFromRaw(static_cast<unsigned int>(n[0]),
          static_cast<unsigned int>(n[1]), static_cast<unsigned int>(n[2]), wanted.Components,
          VTK_FLOAT, const_cast<float*>(wanted.Values->data())))
    {
      error = "could not upload the metric's texture " + wanted.Name + " (" + std::to_string(n[0]) +
        "x" + std::to_string(n[1]) + "x" + std::to_string(n[2]) + ")";
      return false;
    }
    ++this->Uploads;
    kept.push_back(fresh);
  }
  // Step 3: release what this metric no longer reads.
  for (Uploaded& old : this->Textures)
  {
    if (old.Texture)
    {
      old.Texture->ReleaseGraphicsResources(window);
    }
  }
  this->Textures = std::move(kept);
  return true;
}

void MetricTextures::Activate(vtkShaderProgram* program)
{
  for (Uploaded& texture : this->Textures)
  {
    texture.Texture->Activate();
    program->SetUniformi(texture.Uniform.c_str(), texture.Texture->GetTextureUnit());
  }
}

void MetricTextures::Deactivate()
{
  for (Uploaded& texture : this->Textures)
  {
    texture.Texture->Deactivate();
  }
}

void MetricTextures::Release(vtkWindow* window)
{
  for (Uploaded& texture : this->Textures)
  {
    texture.Texture->ReleaseGraphicsResources(window);
  }
  this->Textures.clear();
}
} // namespace riemann
