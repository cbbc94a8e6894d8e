// Shared by the tests and benchmarks of sampled metrics (issue 17): the
// Gaussian lens of Data/metrics/gaussian-lens.json as a tensor volume.
#ifndef RiemannSampledLensImage_h
#define RiemannSampledLensImage_h

#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <cmath>

/// g = n^2 I with n = 1 + 0.5 exp(-|x|^2 / 2), sampled on n^3 points over
/// [low, high]^3, as a 6-component point-data array "Tensors".
inline vtkSmartPointer<vtkImageData> SampledLensImage(int n, double low, double high)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  const double h = (high - low) / (n - 1);
  image->SetOrigin(low, low, low);
  image->SetSpacing(h, h, h);
  vtkNew<vtkDoubleArray> tensors;
  tensors->SetName("Tensors");
  tensors->SetNumberOfComponents(6);
  tensors->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType id = 0; id < tensors->GetNumberOfTuples(); ++id)
  {
    double x[3];
    image->GetPoint(id, x);
    const double index = 1.0 + 0.5 * std::exp(-0.5 * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]));
    const double g[6] = { index * index, index * index, index * index, 0.0, 0.0, 0.0 };
    tensors->SetTuple(id, g);
  }
  image->GetPointData()->AddArray(tensors);
  return image;
}

#endif
