#include "decoded_video.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <stdexcept>

namespace raycam::test {

DecodedVideo decode_video(const std::string& path) {
  AVFormatContext* input = nullptr;
  if (avformat_open_input(&input, path.c_str(), nullptr, nullptr) < 0) throw std::runtime_error("cannot open " + path);
  DecodedVideo video;
  AVCodecContext* decoder = nullptr;
  AVFrame* frame = av_frame_alloc();
  AVPacket* packet = av_packet_alloc();
  SwsContext* to_rgba = nullptr;
  try {
    if (avformat_find_stream_info(input, nullptr) < 0) throw std::runtime_error("no stream info in " + path);
    const int index = av_find_best_stream(input, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (index < 0) throw std::runtime_error("no video stream in " + path);
    AVStream* stream = input->streams[index];
    const AVCodec* codec = avcodec_find_decoder(stream->codecpar->codec_id);
    if (!codec) throw std::runtime_error("no decoder for " + path);
    video.codec = codec->name;
    video.frame_rate = av_q2d(stream->avg_frame_rate);
    decoder = avcodec_alloc_context3(codec);
    avcodec_parameters_to_context(decoder, stream->codecpar);
    if (avcodec_open2(decoder, codec, nullptr) < 0) throw std::runtime_error("cannot open the decoder");
    const auto take_frames = [&] {
      while (avcodec_receive_frame(decoder, frame) == 0) {
        gl::RgbaImage image;
        image.width = frame->width;
        image.height = frame->height;
        image.pixels.resize(std::size_t(image.width) * image.height * 4);
        // The conversion back uses the matrix and range the stream declares (BT.709, limited range, for
        // the YUV videos), as a browser does.
        to_rgba = sws_getCachedContext(to_rgba, frame->width, frame->height, AVPixelFormat(frame->format), frame->width,
                                       frame->height, AV_PIX_FMT_RGBA, SWS_BILINEAR | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
        if (frame->format != AV_PIX_FMT_PAL8) {
          const int space = frame->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT;
          sws_setColorspaceDetails(to_rgba, sws_getCoefficients(space), frame->color_range == AVCOL_RANGE_JPEG,
                                   sws_getCoefficients(space), 1, 0, 1 << 16, 1 << 16);
        }
        std::uint8_t* planes[1] = {image.pixels.data()};
        const int strides[1] = {4 * image.width};
        sws_scale(to_rgba, frame->data, frame->linesize, 0, frame->height, planes, strides);
        if (frame->format != AV_PIX_FMT_PAL8) {
          std::vector<std::uint8_t> y(std::size_t(frame->width) * frame->height);
          for (int row = 0; row < frame->height; ++row)
            std::copy_n(frame->data[0] + row * frame->linesize[0], frame->width, y.begin() + std::ptrdiff_t(row) * frame->width);
          video.luma.push_back(std::move(y));
        }
        video.times.push_back(frame->best_effort_timestamp * av_q2d(stream->time_base));
        video.frames.push_back(std::move(image));
      }
    };
    while (av_read_frame(input, packet) >= 0) {
      if (packet->stream_index == index && avcodec_send_packet(decoder, packet) >= 0) take_frames();
      av_packet_unref(packet);
    }
    avcodec_send_packet(decoder, nullptr);  // drain
    take_frames();
  } catch (...) {
    sws_freeContext(to_rgba);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&decoder);
    avformat_close_input(&input);
    throw;
  }
  sws_freeContext(to_rgba);
  av_packet_free(&packet);
  av_frame_free(&frame);
  avcodec_free_context(&decoder);
  avformat_close_input(&input);
  return video;
}

gl::RgbaImage through_yuv420(const gl::RgbaImage& image) {
  const int w = image.width, h = image.height;
  AVFrame* yuv = av_frame_alloc();
  yuv->format = AV_PIX_FMT_YUV420P;
  yuv->width = w;
  yuv->height = h;
  if (!yuv || av_frame_get_buffer(yuv, 0) < 0) throw std::runtime_error("out of memory");
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  SwsContext* to_yuv = sws_getContext(w, h, AV_PIX_FMT_RGBA, w, h, AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_ACCURATE_RND,
                                      nullptr, nullptr, nullptr);
  sws_setColorspaceDetails(to_yuv, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  const std::uint8_t* in_planes[1] = {image.pixels.data()};
  const int in_strides[1] = {4 * w};
  sws_scale(to_yuv, in_planes, in_strides, 0, h, yuv->data, yuv->linesize);
  SwsContext* to_rgba = sws_getContext(w, h, AV_PIX_FMT_YUV420P, w, h, AV_PIX_FMT_RGBA, SWS_BILINEAR | SWS_ACCURATE_RND,
                                       nullptr, nullptr, nullptr);
  sws_setColorspaceDetails(to_rgba, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
  gl::RgbaImage back;
  back.width = w;
  back.height = h;
  back.pixels.resize(std::size_t(w) * h * 4);
  std::uint8_t* out_planes[1] = {back.pixels.data()};
  const int out_strides[1] = {4 * w};
  sws_scale(to_rgba, yuv->data, yuv->linesize, 0, h, out_planes, out_strides);
  sws_freeContext(to_yuv);
  sws_freeContext(to_rgba);
  av_frame_free(&yuv);
  return back;
}

}  // namespace raycam::test
