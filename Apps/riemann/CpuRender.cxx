#include "CpuRender.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

namespace riemann
{
namespace cli
{
namespace
{
struct Channel
{
  const char* Array;
  int Component;
  const char* Name;
};
}

Image TracerImage(vtkImageData* data, bool aovs)
{
  int dims[3];
  data->GetDimensions(dims);
  std::vector<Channel> channels = { { "Color", 0, "R" }, { "Color", 1, "G" }, { "Color", 2, "B" } };
  if (aovs)
  {
    const std::vector<Channel> more = { { "HitPosition", 0, "HitPosition.X" },
      { "HitPosition", 1, "HitPosition.Y" }, { "HitPosition", 2, "HitPosition.Z" },
      { "ArcLength", 0, "ArcLength" }, { "Steps", 0, "Steps" },
      { "ReasonForTermination", 0, "ReasonForTermination" }, { "SpeedDrift", 0, "SpeedDrift" },
      { "HitError", 0, "HitError" } };
    for (const Channel& channel : more)
    {
      if (data->GetPointData()->GetArray(channel.Array))
      {
        channels.push_back(channel);
      }
    }
  }
  Image image;
  image.Width = dims[0];
  image.Height = dims[1];
  image.Channels = static_cast<int>(channels.size());
  image.Pixels.resize(static_cast<std::size_t>(dims[0]) * dims[1] * channels.size());
  for (std::size_t c = 0; c < channels.size(); ++c)
  {
    image.ChannelNames.push_back(channels[c].Name);
    vtkDataArray* array = data->GetPointData()->GetArray(channels[c].Array);
    for (int row = 0; row < dims[1]; ++row)
    {
      for (int column = 0; column < dims[0]; ++column)
      {
        const vtkIdType source = static_cast<vtkIdType>(row) * dims[0] + column;
        const std::size_t target =
          (static_cast<std::size_t>(dims[1] - 1 - row) * dims[0] + column) * channels.size() + c;
        image.Pixels[target] = static_cast<float>(array->GetComponent(source, channels[c].Component));
      }
    }
  }
  return image;
}

HitErrorSummary SummarizeHitError(vtkImageData* data)
{
  HitErrorSummary summary;
  vtkDataArray* error = data->GetPointData()->GetArray("HitError");
  if (!error)
  {
    return summary;
  }
  std::vector<double> values;
  for (vtkIdType i = 0; i < error->GetNumberOfTuples(); ++i)
  {
    const double e = error->GetComponent(i, 0);
    if (std::isinf(e))
    {
      ++summary.Disagreeing;
    }
    else if (std::isfinite(e))
    {
      values.push_back(e);
    }
  }
  summary.Compared = static_cast<long long>(values.size());
  if (!values.empty())
  {
    std::sort(values.begin(), values.end());
    summary.Maximum = values.back();
    const std::size_t n = values.size();
    summary.Median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    summary.Percentile99 = values[static_cast<std::size_t>(0.99 * (n - 1))];
  }
  return summary;
}

Image HitErrorPicture(vtkImageData* data)
{
  int dims[3];
  data->GetDimensions(dims);
  Image image;
  image.Width = dims[0];
  image.Height = dims[1];
  image.Channels = 3;
  image.ChannelNames = { "R", "G", "B" };
  image.Pixels.assign(static_cast<std::size_t>(dims[0]) * dims[1] * 3, 0.25f);
  vtkDataArray* error = data->GetPointData()->GetArray("HitError");
  if (!error)
  {
    return image;
  }
  // log10(error) in [-7, -1] -> black, blue, green, yellow, white.
  const float stops[5][3] = { { 0, 0, 0 }, { 0.1f, 0.2f, 0.9f }, { 0.1f, 0.8f, 0.3f },
    { 1.0f, 0.9f, 0.1f }, { 1, 1, 1 } };
  for (int row = 0; row < dims[1]; ++row)
  {
    for (int column = 0; column < dims[0]; ++column)
    {
      const double e = error->GetComponent(static_cast<vtkIdType>(row) * dims[0] + column, 0);
      float* p = &image.Pixels[(static_cast<std::size_t>(dims[1] - 1 - row) * dims[0] + column) * 3];
      if (std::isinf(e))
      {
        p[0] = 1.0f;
        p[1] = 0.0f;
        p[2] = 0.0f;
        continue;
      }
      if (!std::isfinite(e))
      {
        continue;
      }
      const double t = std::clamp((std::log10(std::max(e, 1e-12)) + 7.0) / 6.0, 0.0, 1.0) * 4.0;
      const int k = std::min(3, static_cast<int>(t));
      const float f = static_cast<float>(t - k);
      for (int c = 0; c < 3; ++c)
      {
        p[c] = (1 - f) * stops[k][c] + f * stops[k + 1][c];
      }
    }
  }
  return image;
}
} // namespace cli
} // namespace riemann
