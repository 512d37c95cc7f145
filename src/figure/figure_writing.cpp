// Writing figure files: the names (one file, or STEM-ID.EXT per frame), the temporary names renamed once all
// are complete, TikZ as text; SVG, PDF and PNG are painted by cairo (cairo_files.h), which the web page does
// not have (its cairo_files.h answers that the desktop app draws them).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

#include "figure/cairo_files.h"
#include "figure/figure_files.h"
#include "figure/tikz_file.h"

namespace raycam::figure {

namespace {

// Files written under temporary names next to their final ones, renamed together once all are complete
// (a reader never sees half a figure); whatever is not committed is removed.
class PendingFiles {
 public:
  ~PendingFiles() {
    for (const auto& file : files_) std::remove(file.first.c_str());
  }
  std::string add(const std::string& path) {
    // Named before anything is drawn: the drawing library's own reason ("error while writing to output
    // stream") did not say that the folder was the problem.
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder))
      throw std::runtime_error(path + ": cannot write the figure: no folder " + folder.string());
    const std::string temporary = path + ".part" + std::to_string(::getpid());
    files_.push_back({temporary, path});
    return temporary;
  }
  void commit() {
    for (const auto& [temporary, path] : files_)
      if (std::rename(temporary.c_str(), path.c_str()) != 0) throw std::runtime_error(path + ": cannot write the figure");
    files_.clear();
  }

 private:
  std::vector<std::pair<std::string, std::string>> files_;
};

bool one_file(const std::vector<int>& frames, const FigureOutput& output) {
  return frames.size() == 1 || (output.pages && (output.format == Format::pdf || output.format == Format::tikz));
}

std::string file_for(const std::string& path, const std::string& id, Format format, bool one) {
  if (one) return path;
  const std::string ext = std::string(".") + extension(format);
  const bool has_ext = path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
  const std::string stem = has_ext ? path.substr(0, path.size() - ext.size()) : path;
  return stem + "-" + id + ext;
}

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.flush();
  if (!out) throw std::runtime_error(path + ": cannot write the figure");
}

}  // namespace

const char* extension(Format format) {
  switch (format) {
    case Format::svg:
      return "svg";
    case Format::pdf:
      return "pdf";
    case Format::png:
      return "png";
    case Format::tikz:
      return "tex";
  }
  return "";
}

std::vector<std::string> figure_files(const Figure& figure, const std::vector<int>& frames,
                                      const FigureOutput& output, const std::string& path) {
  if (one_file(frames, output)) return {path};
  std::vector<std::string> files;
  for (int index : frames) files.push_back(file_for(path, figure.frames[std::size_t(index)].id, output.format, false));
  return files;
}

WrittenFigure write_figure(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output,
                           const std::string& path) {
  WrittenFigure written;
  PendingFiles pending;
  const std::vector<std::string> files = figure_files(figure, frames, output, path);
  const bool one = files.size() == 1;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::vector<int> these = one ? frames : std::vector<int>{frames[i]};
    const std::string temporary = pending.add(files[i]);
    if (output.format == Format::tikz) {
      write_text_file(temporary, tikz_document(figure, these, output));
      for (int index : these) written.objects_drawn.push_back(int(figure.frames[std::size_t(index)].objects.size()));
    } else {
      write_cairo_file(figure, these, output, temporary, files[i], written);
    }
  }
  pending.commit();
  written.files = files;
  return written;
}

}  // namespace raycam::figure
