// riemann-film-frames FILM.ogv: reads a film back with the Theora codec's
// own decoder (libtheoradec, through libogg: the libraries VTK's
// vtkOggTheoraWriter encodes with) and prints
//
//   frames N width W height H
//   frame K mean-luma Y        (one line per frame, Y in 0..255)
//
// so that tests check what a film holds: its frame count, its size, and that
// its frames differ where the camera moved. Exit 1 with a message when the
// file is not a Theora film. A test tool: not installed.
#include <ogg/ogg.h>
#include <theora/theoradec.h>

#include <cstdio>
#include <cstring>
#include <vector>

namespace
{
/// The mean of the decoded frame's luma plane (the picture region only).
double MeanLuma(th_dec_ctx* decoder, const th_info& info)
{
  th_ycbcr_buffer planes;
  th_decode_ycbcr_out(decoder, planes);
  double sum = 0.0;
  for (unsigned row = 0; row < info.pic_height; ++row)
  {
    const unsigned char* line =
      planes[0].data + static_cast<long>(info.pic_y + row) * planes[0].stride + info.pic_x;
    for (unsigned column = 0; column < info.pic_width; ++column)
    {
      sum += line[column];
    }
  }
  return sum / (static_cast<double>(info.pic_width) * info.pic_height);
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: riemann-film-frames FILM.ogv\n");
    return 2;
  }
  FILE* file = std::fopen(argv[1], "rb");
  if (!file)
  {
    std::fprintf(stderr, "riemann-film-frames: cannot open %s\n", argv[1]);
    return 1;
  }
  ogg_sync_state sync;
  ogg_sync_init(&sync);
  ogg_stream_state stream;
  bool streaming = false;
  th_info info;
  th_comment comment;
  th_setup_info* setup = nullptr;
  th_info_init(&info);
  th_comment_init(&comment);
  th_dec_ctx* decoder = nullptr;
  bool headersDone = false;
  bool broken = false;
  std::vector<double> luma;

  const auto decode = [&](ogg_packet& packet) {
    if (!headersDone)
    {
      const int header = th_decode_headerin(&info, &comment, &setup, &packet);
      if (header > 0)
      {
        return; // a header packet
      }
      if (header < 0)
      {
        broken = true;
        return;
      }
      // 0: the headers are complete and this is the first frame's packet.
      headersDone = true;
      decoder = th_decode_alloc(&info, setup);
    }
    ogg_int64_t granule = 0;
    const int result = th_decode_packetin(decoder, &packet, &granule);
    if (result == 0 || result == TH_DUPFRAME)
    {
      luma.push_back(MeanLuma(decoder, info));
    }
    else
    {
      broken = true;
    }
  };

  ogg_page page;
  ogg_packet packet;
  for (;;)
  {
    char* buffer = ogg_sync_buffer(&sync, 65536);
    const size_t bytes = std::fread(buffer, 1, 65536, file);
    ogg_sync_wrote(&sync, static_cast<long>(bytes));
    while (ogg_sync_pageout(&sync, &page) > 0)
    {
      if (!streaming && ogg_page_bos(&page))
      {
        ogg_stream_init(&stream, ogg_page_serialno(&page));
        streaming = true;
      }
      if (!streaming || ogg_page_serialno(&page) != stream.serialno)
      {
        continue;
      }
      ogg_stream_pagein(&stream, &page);
      while (!broken && ogg_stream_packetout(&stream, &packet) > 0)
      {
        decode(packet);
      }
    }
    if (bytes == 0 || broken)
    {
      break;
    }
  }
  std::fclose(file);
  if (decoder)
  {
    th_decode_free(decoder);
  }
  th_setup_free(setup);
  if (streaming)
  {
    ogg_stream_clear(&stream);
  }
  ogg_sync_clear(&sync);
  if (broken || !headersDone)
  {
    std::fprintf(stderr, "riemann-film-frames: %s is not a whole Theora film\n", argv[1]);
    th_info_clear(&info);
    th_comment_clear(&comment);
    return 1;
  }
  std::printf("frames %zu width %u height %u\n", luma.size(), info.pic_width, info.pic_height);
  for (size_t k = 0; k < luma.size(); ++k)
  {
    std::printf("frame %zu mean-luma %.3f\n", k, luma[k]);
  }
  th_info_clear(&info);
  th_comment_clear(&comment);
  return 0;
}
