#include "stcontact/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "stcontact/io/output_error.hpp"

namespace stc {
namespace {

namespace fs = std::filesystem;

std::string systemMessage(int error) { return std::generic_category().message(error); }

std::string cannotWrite(const fs::path& path, int error) {
  return "cannot write '" + path.string() + "': " + systemMessage(error);
}

/// ".<pid>.<n>", unique among the threads and processes writing into one folder.
std::string uniqueSuffix() {
  static std::atomic<unsigned long> counter{0};
  // Appended in steps: "." + std::string&& trips GCC 12's -Wrestrict false positive (bug 105329).
  std::string suffix(1, '.');
  suffix += std::to_string(::getpid());
  suffix += '.';
  suffix += std::to_string(counter++);
  return suffix;
}

int createExclusive(const fs::path& path) {
  return ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
}


/// An output buffer over a POSIX file descriptor that remembers the errno of the first failed
/// write (std::ofstream loses it), so that the error message can say why.
class FdStreamBuf : public std::streambuf {
 public:
  explicit FdStreamBuf(int fd) : fd_(fd), buffer_(1 << 16) { resetBuffer(); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type ch) override {
    if (!flushBuffer()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }

  std::streamsize xsputn(const char* data, std::streamsize size) override {
    if (size <= epptr() - pptr()) {
      std::memcpy(pptr(), data, static_cast<std::size_t>(size));
      pbump(static_cast<int>(size));
      return size;
    }
    // Larger than the free space: flush and write through, skipping the copy.
    if (!flushBuffer() || !writeAll(data, static_cast<std::size_t>(size))) return 0;
    return size;
  }

  int sync() override { return flushBuffer() ? 0 : -1; }

 private:
  int fd_;
  std::vector<char> buffer_;
  int error_ = 0;

  void resetBuffer() { setp(buffer_.data(), buffer_.data() + buffer_.size()); }

  bool flushBuffer() {
    const bool ok = writeAll(pbase(), static_cast<std::size_t>(pptr() - pbase()));
    resetBuffer();
    return ok;
  }

  bool writeAll(const char* data, std::size_t size) {
    while (error_ == 0 && size > 0) {
      const ssize_t written = ::write(fd_, data, size);
      if (written < 0) {
        if (errno != EINTR) error_ = errno;
        continue;
      }
      data += written;
      size -= static_cast<std::size_t>(written);
    }
    return error_ == 0;
  }
};

}  // namespace

struct AtomicFile::Impl {
  fs::path target;
  fs::path temporary;
  int fd;
  FdStreamBuf buffer;
  std::ostream out;
  bool finished = false;  ///< committed, or failed and cleaned up

  Impl(fs::path target_, fs::path temporary_, int fd_)
      : target(std::move(target_)),
        temporary(std::move(temporary_)),
        fd(fd_),
        buffer(fd_),
        out(&buffer) {}
};

AtomicFile::AtomicFile(fs::path path) {
  if (!path.has_filename())
    throw OutputError("cannot write '" + path.string() + "': not a file name");
  std::string name(1, '.');  // ".NAME.tmp.<pid>.<n>", appended as in uniqueSuffix()
  name += path.filename().string();
  name += ".tmp";
  name += uniqueSuffix();
  fs::path temporary = path.parent_path() / name;
  const int fd = createExclusive(temporary);
  if (fd < 0) {
    const int error = errno;
    throw OutputError(cannotWrite(path, error));
  }
  impl_ = std::make_unique<Impl>(std::move(path), std::move(temporary), fd);
}

AtomicFile::~AtomicFile() { discard(); }
AtomicFile::AtomicFile(AtomicFile&&) noexcept = default;

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
  if (this != &other) {
    discard();
    impl_ = std::move(other.impl_);
  }
  return *this;
}

std::ostream& AtomicFile::stream() {
  if (!impl_ || impl_->finished) throw std::logic_error("AtomicFile::stream() after commit()");
  return impl_->out;
}

const fs::path& AtomicFile::path() const { return impl_->target; }
const fs::path& AtomicFile::temporaryPath() const { return impl_->temporary; }

void AtomicFile::commit() {
  if (!impl_ || impl_->finished)
    throw std::logic_error("AtomicFile::commit() called twice or after a failure");
  Impl& f = *impl_;
  f.out.flush();
  if (!f.out) fail(f.buffer.error() != 0 ? f.buffer.error() : EIO);
  // No fsync: the contract is atomicity against a crashed or killed run (rename is atomic), not
  // durability across a power loss; syncing every VTU frame tripled the seed scene's output time.
  const int closed = ::close(f.fd);
  f.fd = -1;
  if (closed != 0) fail(errno);
  std::error_code ec;
  fs::rename(f.temporary, f.target, ec);
  if (ec) fail(ec.value());
  f.finished = true;
}

void AtomicFile::fail(int error) {
  const std::string message = cannotWrite(impl_->target, error);
  discard();
  throw OutputError(message);
}

void AtomicFile::discard() noexcept {
  if (!impl_ || impl_->finished) return;
  if (impl_->fd >= 0) ::close(impl_->fd);
  impl_->fd = -1;
  ::unlink(impl_->temporary.c_str());
  impl_->finished = true;
}

void writeFileAtomically(const fs::path& path, const std::string& content) {
  AtomicFile file(path);
  file.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  file.commit();
}

void ensureWritableDirectory(const fs::path& dir) {
  if (dir.empty()) throw OutputError("output folder path is empty");
  const std::string quoted = "output folder '" + dir.string() + "'";
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) throw OutputError(quoted + " exists and is not a folder");
  fs::create_directories(dir, ec);
  if (ec) throw OutputError("cannot create " + quoted + ": " + ec.message());
  if (!fs::is_directory(dir, ec)) throw OutputError(quoted + " exists and is not a folder");
  const fs::path probe = dir / (".stc-write-probe" + uniqueSuffix());
  const int fd = createExclusive(probe);
  if (fd < 0) {
    const int error = errno;
    throw OutputError(quoted + " is not writable: " + systemMessage(error));
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace stc
