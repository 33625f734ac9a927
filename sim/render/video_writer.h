#pragma once
// VideoWriter: H.264 MP4 encoding by piping raw RGB frames into an ffmpeg process.

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string_view>
#include <sys/types.h>

#include "sim/render/image.h"

namespace dashbed::render {

/// The full path of an executable found on $PATH, or nullopt.
std::optional<std::filesystem::path> findExecutable(std::string_view name);

/// Whether `ffmpeg` / `ffprobe` is on $PATH.
bool ffmpegAvailable();
bool ffprobeAvailable();

/// Writes an MP4 (H.264, yuv420p, crf 20, preset veryfast) from frames of one size. Runs
///   ffmpeg -y -f rawvideo -pix_fmt rgb24 -s WxH -r FPS -i - -c:v libx264 -pix_fmt yuv420p
///          -preset veryfast -crf 20 OUT
/// with the frames written to its standard input (no shell involved).
class VideoWriter {
 public:
  /// Starts ffmpeg. Throws std::runtime_error if ffmpeg is not on $PATH or cannot be started,
  /// std::invalid_argument for a non-positive or odd size (yuv420p needs even sides) or a
  /// non-positive fps.
  VideoWriter(std::filesystem::path out_mp4, int width, int height, double fps);
  /// Finishes the file if finish() was not called (errors are then ignored).
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  /// Appends one frame. Throws std::invalid_argument for a frame of another size, and
  /// std::runtime_error (with ffmpeg's messages) if ffmpeg has stopped reading.
  void add(const Image& frame);

  /// Closes the stream and waits for ffmpeg. Throws std::runtime_error with ffmpeg's messages
  /// if it exits with an error. Calling it again does nothing.
  void finish();

  int frameCount() const { return frames_; }
  const std::filesystem::path& path() const { return out_; }

 private:
  // Waits for ffmpeg and returns its exit status (-1 if it did not exit normally).
  int reap();
  std::string ffmpegMessages();

  std::filesystem::path out_;
  int width_;
  int height_;
  int frames_ = 0;
  pid_t pid_ = -1;
  int pipe_fd_ = -1;          // write end of ffmpeg's stdin
  std::FILE* log_ = nullptr;  // ffmpeg's stderr (an unnamed temporary file)
};

}  // namespace dashbed::render
