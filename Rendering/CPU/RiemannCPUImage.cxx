#include "RiemannCPUImage.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>

namespace riemann
{
namespace
{
/// One channel of the picture: its name and how to read it off a pixel.
struct Channel
{
  std::string Name;
  std::function<float(const PixelResult&)> Value;
};

std::vector<Channel> Channels(bool aovs, bool hitError)
{
  std::vector<Channel> channels = { { "R", [](const PixelResult& p) { return p.Color[0]; } },
    { "G", [](const PixelResult& p) { return p.Color[1]; } },
    { "B", [](const PixelResult& p) { return p.Color[2]; } } };
  if (!aovs)
  {
    return channels;
  }
  const std::vector<Channel> more = {
    { "HitPosition.X", [](const PixelResult& p) { return p.HitPosition[0]; } },
    { "HitPosition.Y", [](const PixelResult& p) { return p.HitPosition[1]; } },
    { "HitPosition.Z", [](const PixelResult& p) { return p.HitPosition[2]; } },
    { "ArcLength", [](const PixelResult& p) { return p.ArcLength; } },
    { "Steps", [](const PixelResult& p) { return static_cast<float>(p.Steps); } },
    { "ReasonForTermination", [](const PixelResult& p) { return static_cast<float>(p.Reason); } },
    { "SpeedDrift", [](const PixelResult& p) { return p.SpeedDrift; } },
  };
  channels.insert(channels.end(), more.begin(), more.end());
  if (hitError)
  {
    channels.push_back({ "HitError", [](const PixelResult& p) { return p.HitError; } });
  }
  return channels;
}

/// Index of the pixel shown at `row` (0 at the top) and `column`.
std::size_t SourcePixel(int row, int column, int width, int height)
{
  return static_cast<std::size_t>(height - 1 - row) * width + column;
}
} // namespace

Image PixelImage(
  const std::vector<PixelResult>& pixels, int width, int height, bool aovs, bool hitError)
{
  const std::vector<Channel> channels = Channels(aovs, hitError);
  Image image;
  image.Width = width;
  image.Height = height;
  image.Channels = static_cast<int>(channels.size());
  image.Pixels.resize(static_cast<std::size_t>(width) * height * channels.size());
  for (const Channel& channel : channels)
  {
    image.ChannelNames.push_back(channel.Name);
  }
  std::size_t target = 0;
  for (int row = 0; row < height; ++row)
  {
    for (int column = 0; column < width; ++column)
    {
      const PixelResult& pixel = pixels[SourcePixel(row, column, width, height)];
      for (const Channel& channel : channels)
      {
        image.Pixels[target++] = channel.Value(pixel);
      }
    }
  }
  return image;
}

HitErrorSummary SummarizeHitError(const std::vector<PixelResult>& pixels)
{
  HitErrorSummary summary;
  std::vector<double> values;
  for (const PixelResult& pixel : pixels)
  {
    const double e = pixel.HitError;
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

Image HitErrorPicture(const std::vector<PixelResult>& pixels, int width, int height)
{
  Image image;
  image.Width = width;
  image.Height = height;
  image.Channels = 3;
  image.ChannelNames = { "R", "G", "B" };
  image.Pixels.assign(static_cast<std::size_t>(width) * height * 3, 0.25f);
  // log10(error) in [-7, -1] -> black, blue, green, yellow, white.
  const float stops[5][3] = { { 0, 0, 0 }, { 0.1f, 0.2f, 0.9f }, { 0.1f, 0.8f, 0.3f },
    { 1.0f, 0.9f, 0.1f }, { 1, 1, 1 } };
  for (int row = 0; row < height; ++row)
  {
    for (int column = 0; column < width; ++column)
    {
      const double e = pixels[SourcePixel(row, column, width, height)].HitError;
      float* p = &image.Pixels[(static_cast<std::size_t>(row) * width + column) * 3];
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
} // namespace riemann
