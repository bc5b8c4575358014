#include "storage/durable_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace haptics {

namespace {

class FileDescriptor {
public:
	explicit FileDescriptor(int p_fd) :
			fd_(p_fd) {}
	FileDescriptor(const FileDescriptor &) = delete;
	FileDescriptor &operator=(const FileDescriptor &) = delete;
	~FileDescriptor() {
		if (fd_ >= 0) {
			::close(fd_);
		}
	}
	int get() const { return fd_; }
	// Closing can report a deferred write error, so it is checked, not left to the destructor.
	int close() {
		const int result = ::close(fd_);
		fd_ = -1;
		return result;
	}

private:
	int fd_;
};

Status io_error(const char *p_what, const std::string &p_path) {
	return Status::error(StatusCode::DEVICE_ERROR, "%s '%s': %s", p_what, p_path.c_str(),
			std::strerror(errno));
}

std::string parent_of(const std::string &p_path) {
	const size_t slash = p_path.find_last_of('/');
	if (slash == std::string::npos) {
		return ".";
	}
	return slash == 0 ? "/" : p_path.substr(0, slash);
}

Status sync_directory(const std::string &p_dir) {
	FileDescriptor dir(::open(p_dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
	if (dir.get() < 0) {
		return io_error("cannot open folder", p_dir);
	}
	if (::fsync(dir.get()) != 0) {
		return io_error("cannot sync folder", p_dir);
	}
	return Status::success();
}

Status write_all(int p_fd, std::string_view p_data, const std::string &p_path) {
	size_t written = 0;
	while (written < p_data.size()) {
		const ssize_t n = ::write(p_fd, p_data.data() + written, p_data.size() - written);
		if (n < 0) {
			if (errno == EINTR) {
				continue;
			}
			return io_error("cannot write", p_path);
		}
		written += static_cast<size_t>(n);
	}
	return Status::success();
}

bool exists(const std::string &p_path) {
	struct stat info {};
	return ::stat(p_path.c_str(), &info) == 0;
}

} // namespace

Status durable_append(const std::string &p_path, std::string_view p_data) {
	const bool is_new = !exists(p_path);
	FileDescriptor file(::open(p_path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644));
	if (file.get() < 0) {
		return io_error("cannot open", p_path);
	}
	Status status = write_all(file.get(), p_data, p_path);
	if (!status.ok()) {
		return status;
	}
	if (::fsync(file.get()) != 0) {
		return io_error("cannot sync", p_path);
	}
	if (file.close() != 0) {
		return io_error("cannot close", p_path);
	}
	return is_new ? sync_directory(parent_of(p_path)) : Status::success();
}

Status durable_write(const std::string &p_path, std::string_view p_data, bool p_replace) {
	if (!p_replace && exists(p_path)) {
		return Status::error(StatusCode::INVALID_STATE, "'%s' exists and is never overwritten",
				p_path.c_str());
	}
	const std::string temporary = p_path + ".tmp";
	{
		FileDescriptor file(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
		if (file.get() < 0) {
			return io_error("cannot create", temporary);
		}
		Status status = write_all(file.get(), p_data, temporary);
		if (!status.ok()) {
			::unlink(temporary.c_str());
			return status;
		}
		if (::fsync(file.get()) != 0 || file.close() != 0) {
			Status failed = io_error("cannot sync", temporary);
			::unlink(temporary.c_str());
			return failed;
		}
	}
	if (::rename(temporary.c_str(), p_path.c_str()) != 0) {
		Status failed = io_error("cannot rename into", p_path);
		::unlink(temporary.c_str());
		return failed;
	}
	return sync_directory(parent_of(p_path));
}

Status make_directories(const std::string &p_path) {
	if (p_path.empty()) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "empty folder path");
	}
	std::string partial;
	size_t position = 0;
	while (position != std::string::npos) {
		position = p_path.find('/', position + 1);
		partial = p_path.substr(0, position);
		if (partial.empty() || exists(partial)) {
			continue;
		}
		if (::mkdir(partial.c_str(), 0755) != 0 && errno != EEXIST) {
			return io_error("cannot create folder", partial);
		}
	}
	return Status::success();
}

Status check_complete_lines(const std::string &p_path, bool &r_complete) {
	FileDescriptor file(::open(p_path.c_str(), O_RDONLY | O_CLOEXEC));
	if (file.get() < 0) {
		return io_error("cannot open", p_path);
	}
	const off_t size = ::lseek(file.get(), 0, SEEK_END);
	if (size < 0) {
		return io_error("cannot read", p_path);
	}
	if (size == 0) {
		r_complete = true;
		return Status::success();
	}
	char last = 0;
	if (::pread(file.get(), &last, 1, size - 1) != 1) {
		return io_error("cannot read", p_path);
	}
	r_complete = last == '\n';
	return Status::success();
}

} // namespace haptics
