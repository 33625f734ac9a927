#include "sim/render/video_writer.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <pthread.h>
#include <spawn.h>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace dashbed::render {

namespace {

// Writes all of `data` to `fd` with SIGPIPE blocked in this thread, so that a dead reader
// shows up as EPIPE instead of killing the process; a SIGPIPE raised here is consumed.
// Returns 0 or the errno of the failed write.
int writeAll(int fd, const std::uint8_t* data, std::size_t size) {
  sigset_t pipe_signal, old_mask, pending;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &old_mask);
  sigpending(&pending);
  const bool was_pending = sigismember(&pending, SIGPIPE) == 1;
  int error = 0;
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      error = errno;
      break;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  if (error == EPIPE && !was_pending) {
    const timespec no_wait{0, 0};
    sigtimedwait(&pipe_signal, nullptr, &no_wait);
  }
  pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
  return error;
}

}  // namespace

std::optional<std::filesystem::path> findExecutable(std::string_view name) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  const std::string_view dirs(path);
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string dir(dirs.substr(start, end - start));
    const std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : dir) / name;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return std::nullopt;
}

bool ffmpegAvailable() { return findExecutable("ffmpeg").has_value(); }
bool ffprobeAvailable() { return findExecutable("ffprobe").has_value(); }

VideoWriter::VideoWriter(std::filesystem::path out_mp4, int width, int height, double fps)
    : out_(std::move(out_mp4)), width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0) {
    throw std::invalid_argument("VideoWriter: " + out_.string() + ": frame size must be positive and even (got " +
                                std::to_string(width) + "x" + std::to_string(height) + ")");
  }
  if (!(fps > 0.0) || !std::isfinite(fps)) {
    throw std::invalid_argument("VideoWriter: " + out_.string() + ": fps must be positive (got " +
                                std::to_string(fps) + ")");
  }
  const std::optional<std::filesystem::path> ffmpeg = findExecutable("ffmpeg");
  if (!ffmpeg) {
    throw std::runtime_error("cannot write video " + out_.string() +
                             ": ffmpeg is not on PATH (install it, e.g. apt-get install ffmpeg)");
  }

  char fps_text[32];
  std::snprintf(fps_text, sizeof(fps_text), "%.9g", fps);
  const std::string size_text = std::to_string(width) + "x" + std::to_string(height);
  // ffmpeg turns its keyboard interaction off by itself when the input is stdin ("-i -")
  std::vector<std::string> args{ffmpeg->string(), "-hide_banner", "-loglevel", "error",    "-y",
                                "-f",             "rawvideo",     "-pix_fmt",  "rgb24",    "-s",
                                size_text,        "-r",           fps_text,    "-i",       "-",
                                "-c:v",           "libx264",      "-pix_fmt",  "yuv420p",  "-preset",
                                "veryfast",       "-crf",         "20",        out_.string()};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);

  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("VideoWriter: pipe failed: " + std::string(std::strerror(errno)));
  log_ = std::tmpfile();
  if (!log_) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error("VideoWriter: cannot create a temporary file for ffmpeg's messages");
  }
  ::fcntl(fileno(log_), F_SETFD, FD_CLOEXEC);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, fileno(log_), STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t no_signals, default_signals;
  sigemptyset(&no_signals);
  sigemptyset(&default_signals);
  sigaddset(&default_signals, SIGPIPE);
  posix_spawnattr_setsigmask(&attributes, &no_signals);
  posix_spawnattr_setsigdefault(&attributes, &default_signals);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  const int spawn_error = ::posix_spawn(&pid_, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(fds[0]);
  if (spawn_error != 0) {
    ::close(fds[1]);
    std::fclose(log_);
    log_ = nullptr;
    pid_ = -1;
    throw std::runtime_error("cannot start " + ffmpeg->string() + ": " + std::strerror(spawn_error));
  }
  pipe_fd_ = fds[1];
}

VideoWriter::~VideoWriter() {
  try {
    finish();
  } catch (...) {
    // a destructor must not throw; callers who care call finish() themselves
  }
  if (log_) std::fclose(log_);
}

std::string VideoWriter::ffmpegMessages() {
  if (!log_) return "";
  std::fflush(log_);
  std::rewind(log_);
  std::string text;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof(buffer), log_)) > 0) text.append(buffer, n);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  // the end says what went wrong
  if (text.size() > 2000) text = "..." + text.substr(text.size() - 2000);
  return text.empty() ? "(no message)" : text;
}

int VideoWriter::reap() {
  if (pipe_fd_ >= 0) {
    ::close(pipe_fd_);
    pipe_fd_ = -1;
  }
  if (pid_ < 0) return 0;
  int status = 0;
  pid_t result;
  do {
    result = ::waitpid(pid_, &status, 0);
  } while (result < 0 && errno == EINTR);
  pid_ = -1;
  if (result < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void VideoWriter::add(const Image& frame) {
  if (frame.width != width_ || frame.height != height_ ||
      frame.rgb.size() != static_cast<std::size_t>(width_) * height_ * 3) {
    throw std::invalid_argument("VideoWriter: " + out_.string() + ": frame of " + std::to_string(frame.width) + "x" +
                                std::to_string(frame.height) + " for a video of " + std::to_string(width_) + "x" +
                                std::to_string(height_));
  }
  if (pipe_fd_ < 0) throw std::runtime_error("VideoWriter: " + out_.string() + ": add() after finish()");
  const int error = writeAll(pipe_fd_, frame.rgb.data(), frame.rgb.size());
  if (error != 0) {
    const int status = reap();
    throw std::runtime_error("ffmpeg stopped reading frames for " + out_.string() + " (" + std::strerror(error) +
                             ", exit status " + std::to_string(status) + "): " + ffmpegMessages());
  }
  ++frames_;
}

void VideoWriter::finish() {
  if (pid_ < 0 && pipe_fd_ < 0) return;
  const int status = reap();
  if (status != 0) {
    throw std::runtime_error("ffmpeg failed writing " + out_.string() + " (exit status " + std::to_string(status) +
                             "): " + ffmpegMessages());
  }
}

}  // namespace dashbed::render
