#include "video/video_writer.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "raycam/image_files.h"

namespace raycam::video {

namespace fs = std::filesystem;

namespace {
bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

std::string av_message(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

// One fixed palette for the whole GIF, from the first frame: the window's colours are flat and few (panels,
// text, the scene's colours), so the most frequent 15-bit colours, each the mean of the pixels it holds,
// cover it. Every later pixel takes the nearest entry (looked up once per 15-bit colour).
class GifPalette {
 public:
  explicit GifPalette(const std::uint8_t* rgba, std::size_t pixels) {
    std::vector<std::array<std::uint64_t, 4>> bins(1 << 15, {0, 0, 0, 0});  // count, r, g, b sums
    for (std::size_t i = 0; i < pixels; ++i) {
      const std::uint8_t* p = rgba + 4 * i;
      auto& bin = bins[key(p)];
      ++bin[0], bin[1] += p[0], bin[2] += p[1], bin[3] += p[2];
    }
    std::vector<int> order;
    for (int k = 0; k < (1 << 15); ++k)
      if (bins[k][0] > 0) order.push_back(k);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return bins[a][0] > bins[b][0]; });
    order.resize(std::min<std::size_t>(order.size(), 256));
    for (int k : order) {
      const auto& bin = bins[k];
      colours_.push_back({std::uint8_t(bin[1] / bin[0]), std::uint8_t(bin[2] / bin[0]), std::uint8_t(bin[3] / bin[0])});
    }
    lookup_.assign(1 << 15, -1);
  }
  // ARGB words as FFmpeg's PAL8 palette holds them; unused entries black.
  void fill(std::uint32_t* palette) const {
    for (int i = 0; i < 256; ++i) {
      const std::array<std::uint8_t, 3> c = i < int(colours_.size()) ? colours_[i] : std::array<std::uint8_t, 3>{0, 0, 0};
      palette[i] = 0xFF000000u | (std::uint32_t(c[0]) << 16) | (std::uint32_t(c[1]) << 8) | c[2];
    }
  }
  std::uint8_t index(const std::uint8_t* p) {
    int& entry = lookup_[key(p)];
    if (entry < 0) {
      // The 15-bit colour's centre against every entry (weighted like the eye: green counts most).
      const int r = (p[0] & 0xF8) | 4, g = (p[1] & 0xF8) | 4, b = (p[2] & 0xF8) | 4;
      long best = -1;
      for (std::size_t i = 0; i < colours_.size(); ++i) {
        const long dr = r - colours_[i][0], dg = g - colours_[i][1], db = b - colours_[i][2];
        const long distance = 3 * dr * dr + 4 * dg * dg + 2 * db * db;
        if (best < 0 || distance < best) best = distance, entry = int(i);
      }
    }
    return std::uint8_t(entry);
  }

 private:
  static int key(const std::uint8_t* p) { return (p[0] >> 3) << 10 | (p[1] >> 3) << 5 | (p[2] >> 3); }
  std::vector<std::array<std::uint8_t, 3>> colours_;
  std::vector<int> lookup_;
};
}  // namespace

std::optional<VideoFormat> format_of(const std::string& path) {
  if (path.empty()) return std::nullopt;
  if (ends_with(path, "/")) return VideoFormat::png_folder;
  std::error_code error;
  if (fs::is_directory(path, error)) return VideoFormat::png_folder;
  if (ends_with(path, ".mp4")) return VideoFormat::mp4;
  if (ends_with(path, ".webm")) return VideoFormat::webm;
  if (ends_with(path, ".gif")) return VideoFormat::gif;
  if (ends_with(path, ".mkv")) return VideoFormat::mkv;
  // One integer conversion (%d, %03d, …) in the file name, ending in .png.
  const std::size_t percent = path.find('%');
  if (ends_with(path, ".png") && percent != std::string::npos && path.find('%', percent + 1) == std::string::npos &&
      path.find('/', percent) == std::string::npos) {
    std::size_t i = percent + 1;
    while (i < path.size() && std::isdigit(static_cast<unsigned char>(path[i]))) ++i;
    if (i < path.size() && path[i] == 'd' && i - percent <= 3) return VideoFormat::png_pattern;
  }
  return std::nullopt;
}

const char* accepted_outputs() { return "FILE.mp4, FILE.webm, FILE.gif, FILE.mkv, a FOLDER/ or a PATTERN%03d.png"; }

const char* format_name(VideoFormat format) {
  switch (format) {
    case VideoFormat::mp4: return "H.264 MP4";
    case VideoFormat::webm: return "VP9 WebM";
    case VideoFormat::gif: return "animated GIF";
    case VideoFormat::mkv: return "lossless FFV1 Matroska";
    case VideoFormat::png_folder: return "PNG folder";
    case VideoFormat::png_pattern: return "PNG sequence";
  }
  return "?";
}

std::string side_rule(VideoFormat format, int side) {
  // yuv420p keeps one colour sample per 2×2 pixels: libx264 refuses odd sides; VP9 takes them, but the
  // same rule keeps the two video formats alike (and every browser's decoder happy).
  if ((format == VideoFormat::mp4 || format == VideoFormat::webm) && side % 2 != 0)
    return "an even number of pixels (H.264 and VP9 in yuv420p, the format browsers play)";
  return "";
}

struct VideoWriter::State {
  std::string path, temporary;
  VideoFormat format;
  VideoSettings settings;
  int frames = 0;
  bool finished = false;
  // FFmpeg's
  AVFormatContext* muxer = nullptr;
  AVCodecContext* encoder = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scaler = nullptr;
  std::unique_ptr<GifPalette> palette;
  // PNG sequences: the frames' names in the temporary folder and, for a pattern, their final names
  std::vector<std::string> pattern_names;

  ~State() {
    if (scaler) sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&encoder);
    if (muxer) {
      if (muxer->pb) avio_closep(&muxer->pb);
      avformat_free_context(muxer);
    }
  }

  bool is_png() const { return format == VideoFormat::png_folder || format == VideoFormat::png_pattern; }

  [[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(what); }

  void open_video() {
    av_log_set_level(AV_LOG_ERROR);  // the encoders' statistics are not the user's business; errors are
    const char* muxer_name = format == VideoFormat::mp4    ? "mp4"
                             : format == VideoFormat::webm ? "webm"
                             : format == VideoFormat::mkv  ? "matroska"
                                                           : "gif";
    if (avformat_alloc_output_context2(&muxer, nullptr, muxer_name, temporary.c_str()) < 0 || !muxer)
      fail("FFmpeg has no " + std::string(muxer_name) + " muxer");
    const AVCodec* codec = format == VideoFormat::mp4    ? avcodec_find_encoder_by_name("libx264")
                           : format == VideoFormat::webm ? avcodec_find_encoder_by_name("libvpx-vp9")
                           : format == VideoFormat::mkv  ? avcodec_find_encoder(AV_CODEC_ID_FFV1)
                                                         : avcodec_find_encoder(AV_CODEC_ID_GIF);
    if (!codec) fail(std::string("FFmpeg (libavcodec) has no encoder for ") + format_name(format));
    stream = avformat_new_stream(muxer, nullptr);
    encoder = avcodec_alloc_context3(codec);
    if (!stream || !encoder) fail("FFmpeg: out of memory");
    encoder->width = settings.width;
    encoder->height = settings.height;
    encoder->time_base = AVRational{1, settings.fps};
    encoder->framerate = AVRational{settings.fps, 1};
    AVDictionary* options = nullptr;
    if (format == VideoFormat::gif) {
      encoder->pix_fmt = AV_PIX_FMT_PAL8;
    } else if (format == VideoFormat::mkv) {
      // The window's pixels as they are: 8-bit RGB (BGR0 is a reordering of RGBA, no colour conversion), every
      // frame a key frame (FFV1's intra coding): an instructor's master copy, and the test of every frame.
      encoder->pix_fmt = AV_PIX_FMT_BGR0;
      encoder->gop_size = 1;
      encoder->thread_count = 0;
    } else {
      encoder->pix_fmt = AV_PIX_FMT_YUV420P;
      encoder->gop_size = 2 * settings.fps;  // a key frame every 2 s: a course page can seek
      encoder->color_range = AVCOL_RANGE_MPEG;
      encoder->colorspace = AVCOL_SPC_BT709;
      encoder->color_primaries = AVCOL_PRI_BT709;
      encoder->color_trc = AVCOL_TRC_IEC61966_2_1;  // sRGB: what the window's pixels are
      encoder->thread_count = 0;                    // FFmpeg picks (every core)
    }
    if (format == VideoFormat::mp4) {
      // Fast enough for real time at 720p on two cores, and sharp text (measured: docs/cli.md).
      av_dict_set(&options, "preset", "veryfast", 0);
      av_dict_set(&options, "crf", "18", 0);
      av_dict_set(&options, "tune", "animation", 0);  // flat areas and sharp edges, as the window has
    } else if (format == VideoFormat::webm) {
      av_dict_set(&options, "deadline", "realtime", 0);
      av_dict_set(&options, "cpu-used", "8", 0);
      av_dict_set(&options, "row-mt", "1", 0);
      av_dict_set(&options, "crf", "20", 0);
      av_dict_set(&options, "b", "0", 0);  // constant quality
    }
    if (muxer->oformat->flags & AVFMT_GLOBALHEADER) encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    const int opened = avcodec_open2(encoder, codec, &options);
    av_dict_free(&options);
    if (opened < 0) fail(std::string("cannot open the ") + format_name(format) + " encoder: " + av_message(opened));
    if (avcodec_parameters_from_context(stream->codecpar, encoder) < 0) fail("FFmpeg: cannot copy the parameters");
    stream->time_base = encoder->time_base;
    stream->avg_frame_rate = encoder->framerate;
    const int io = avio_open(&muxer->pb, temporary.c_str(), AVIO_FLAG_WRITE);
    if (io < 0) fail("cannot write " + temporary + ": " + av_message(io));
    AVDictionary* mux_options = nullptr;
    if (format == VideoFormat::mp4) av_dict_set(&mux_options, "movflags", "+faststart", 0);  // plays while loading
    const int header = avformat_write_header(muxer, &mux_options);
    av_dict_free(&mux_options);
    if (header < 0) fail("cannot write " + temporary + ": " + av_message(header));
    frame = av_frame_alloc();
    packet = av_packet_alloc();
    if (!frame || !packet) fail("FFmpeg: out of memory");
    frame->format = encoder->pix_fmt;
    frame->width = settings.width;
    frame->height = settings.height;
    if (av_frame_get_buffer(frame, 0) < 0) fail("FFmpeg: out of memory");
    if (format == VideoFormat::mkv) {
      scaler = sws_getContext(settings.width, settings.height, AV_PIX_FMT_RGBA, settings.width, settings.height,
                              AV_PIX_FMT_BGR0, SWS_POINT, nullptr, nullptr, nullptr);
      if (!scaler) fail("swscale: cannot convert RGBA to bgr0");
    } else if (format != VideoFormat::gif) {
      scaler = sws_getContext(settings.width, settings.height, AV_PIX_FMT_RGBA, settings.width, settings.height,
                              AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
      if (!scaler) fail("swscale: cannot convert RGBA to yuv420p");
      const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
      sws_setColorspaceDetails(scaler, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);  // full-range RGB → limited YUV
    }
  }

  // Sends `input` (nullptr: the end) and writes every packet the encoder has ready.
  void encode(AVFrame* input) {
    int sent = avcodec_send_frame(encoder, input);
    if (sent < 0) fail(std::string("the ") + format_name(format) + " encoder failed: " + av_message(sent));
    for (;;) {
      const int received = avcodec_receive_packet(encoder, packet);
      if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
      if (received < 0) fail(std::string("the ") + format_name(format) + " encoder failed: " + av_message(received));
      av_packet_rescale_ts(packet, encoder->time_base, stream->time_base);
      packet->stream_index = stream->index;
      const int written = av_interleaved_write_frame(muxer, packet);
      if (written < 0) fail("cannot write " + temporary + ": " + av_message(written));
    }
  }

  void add_video_frame(const std::uint8_t* rgba) {
    if (av_frame_make_writable(frame) < 0) fail("FFmpeg: out of memory");
    const int w = settings.width, h = settings.height;
    if (format == VideoFormat::gif) {
      if (!palette) palette = std::make_unique<GifPalette>(rgba, std::size_t(w) * h);
      palette->fill(reinterpret_cast<std::uint32_t*>(frame->data[1]));
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) frame->data[0][y * frame->linesize[0] + x] = palette->index(rgba + 4 * (std::size_t(y) * w + x));
    } else {
      const std::uint8_t* planes[1] = {rgba};
      const int strides[1] = {4 * w};
      sws_scale(scaler, planes, strides, 0, h, frame->data, frame->linesize);
    }
    frame->pts = frames;
    encode(frame);
  }

  void finish_video() {
    encode(nullptr);
    const int trailer = av_write_trailer(muxer);
    if (trailer < 0) fail("cannot write " + temporary + ": " + av_message(trailer));
    const bool io_error = muxer->pb->error < 0;
    const int closed = avio_closep(&muxer->pb);
    if (io_error || closed < 0) fail("cannot write " + temporary + ": " + av_message(io_error ? AVERROR(EIO) : closed));
  }

  void remove_temporary() {
    std::error_code ignored;
    if (is_png()) fs::remove_all(temporary, ignored);
    else fs::remove(temporary, ignored);
  }
};

VideoWriter::VideoWriter(const std::string& path, VideoFormat format, const VideoSettings& settings)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = path;
  s.format = format;
  s.settings = settings;
  for (const int side : {settings.width, settings.height})
    if (const std::string rule = side_rule(format, side); !rule.empty())
      throw std::invalid_argument(std::string(format_name(format)) + ": expected " + rule + ", got " + std::to_string(side));
  // The temporary name sits beside the final one (a rename within a folder is atomic), and is made unique
  // by mkstemp/mkdtemp so that two recordings never share it.
  std::string base = path;
  while (base.size() > 1 && base.back() == '/') base.pop_back();
  if (format == VideoFormat::png_pattern) {
    // A pattern's folder is made as a FOLDER/ output is (frames/f%03d.png: "frames" may not exist yet).
    const fs::path folder = fs::path(path).parent_path();
    std::error_code ignored;
    if (!folder.empty()) fs::create_directories(folder, ignored);
    base = (folder / ".raycam-frames").string();
  }
  std::vector<char> name(base.begin(), base.end());
  const std::string suffix = ".tmp-XXXXXX";
  name.insert(name.end(), suffix.begin(), suffix.end());
  name.push_back('\0');
  // mkstemp and mkdtemp make their files private; the video gets the permissions any new file would.
  const mode_t mask = umask(0);
  umask(mask);
  if (s.is_png()) {
    if (!mkdtemp(name.data())) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    s.temporary = name.data();
    chmod(s.temporary.c_str(), 0777 & ~mask);
    return;
  }
  const int fd = mkstemp(name.data());
  if (fd < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  fchmod(fd, 0666 & ~mask);
  close(fd);
  s.temporary = name.data();
  try {
    s.open_video();
  } catch (...) {
    s.remove_temporary();
    throw;
  }
}

VideoWriter::~VideoWriter() {
  if (state_ && !state_->finished) state_->remove_temporary();
}

void VideoWriter::add_frame(const std::uint8_t* rgba) {
  State& s = *state_;
  if (s.is_png()) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%05d.png", s.frames);
    write_png_pixels(rgba, s.settings.width, s.settings.height, 4, false, s.temporary + "/" + name);
    if (s.format == VideoFormat::png_pattern) {
      std::vector<char> final_name(s.path.size() + 32);
      std::snprintf(final_name.data(), final_name.size(), s.path.c_str(), s.frames);
      s.pattern_names.push_back(final_name.data());
    }
  } else {
    s.add_video_frame(rgba);
  }
  ++s.frames;
}

void VideoWriter::finish() {
  State& s = *state_;
  if (!s.is_png()) s.finish_video();
  std::error_code error;
  if (s.format == VideoFormat::png_pattern) {
    for (int k = 0; k < s.frames && !error; ++k) {
      char name[64];
      std::snprintf(name, sizeof name, "frame_%05d.png", k);
      fs::rename(s.temporary + "/" + name, s.pattern_names[std::size_t(k)], error);
    }
    if (!error) fs::remove(s.temporary, error);
  } else {
    std::string target = s.path;
    while (target.size() > 1 && target.back() == '/') target.pop_back();
    fs::rename(s.temporary, target, error);  // a folder replaces an empty one
  }
  if (error) throw std::runtime_error("cannot rename " + s.temporary + " to " + s.path + ": " + error.message());
  s.finished = true;
}

int VideoWriter::frames_written() const { return state_->frames; }
const std::string& VideoWriter::temporary_path() const { return state_->temporary; }

}  // namespace raycam::video
