#include "storage/durable_file.h"

#include <algorithm>

#include <windows.h>

namespace haptics {

namespace {

class FileHandle {
public:
	explicit FileHandle(HANDLE p_handle) :
			handle_(p_handle) {}
	FileHandle(const FileHandle &) = delete;
	FileHandle &operator=(const FileHandle &) = delete;
	~FileHandle() {
		if (valid()) {
			CloseHandle(handle_);
		}
	}
	bool valid() const { return handle_ != INVALID_HANDLE_VALUE; }
	HANDLE get() const { return handle_; }
	// Closing is checked, as on POSIX, rather than left to the destructor.
	bool close() {
		const bool closed = CloseHandle(handle_) != 0;
		handle_ = INVALID_HANDLE_VALUE;
		return closed;
	}

private:
	HANDLE handle_;
};

std::wstring widen(const std::string &p_utf8) {
	if (p_utf8.empty()) {
		return std::wstring();
	}
	const int length = MultiByteToWideChar(CP_UTF8, 0, p_utf8.data(), static_cast<int>(p_utf8.size()), nullptr, 0);
	std::wstring wide(static_cast<size_t>(std::max(length, 0)), L'\0');
	MultiByteToWideChar(CP_UTF8, 0, p_utf8.data(), static_cast<int>(p_utf8.size()), wide.data(), length);
	return wide;
}

// GetLastError() in words (FormatMessage's system text, without its line break).
Status io_error(const char *p_what, const std::string &p_path) {
	const DWORD code = GetLastError();
	char text[256] = {};
	const DWORD length = FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr, code, 0,
			text, sizeof(text), nullptr);
	size_t end = length;
	while (end > 0 && (text[end - 1] == '\n' || text[end - 1] == '\r' || text[end - 1] == '.')) {
		--end;
	}
	text[end] = '\0';
	return Status::error(StatusCode::DEVICE_ERROR, "%s '%s': %s (Windows error %lu)", p_what, p_path.c_str(),
			end > 0 ? text : "unknown error", static_cast<unsigned long>(code));
}

bool exists(const std::string &p_path) {
	return GetFileAttributesW(widen(p_path).c_str()) != INVALID_FILE_ATTRIBUTES;
}

Status write_all(HANDLE p_file, std::string_view p_data, const std::string &p_path) {
	size_t written = 0;
	while (written < p_data.size()) {
		const DWORD chunk = static_cast<DWORD>(std::min<size_t>(p_data.size() - written, 1u << 30));
		DWORD n = 0;
		if (!WriteFile(p_file, p_data.data() + written, chunk, &n, nullptr)) {
			return io_error("cannot write", p_path);
		}
		written += n;
	}
	return Status::success();
}

} // namespace

Status durable_append(const std::string &p_path, std::string_view p_data) {
	FileHandle file(CreateFileW(widen(p_path).c_str(), FILE_APPEND_DATA, FILE_SHARE_READ, nullptr, OPEN_ALWAYS,
			FILE_ATTRIBUTE_NORMAL, nullptr));
	if (!file.valid()) {
		return io_error("cannot open", p_path);
	}
	Status status = write_all(file.get(), p_data, p_path);
	if (!status.ok()) {
		return status;
	}
	if (!FlushFileBuffers(file.get())) {
		return io_error("cannot sync", p_path);
	}
	return file.close() ? Status::success() : io_error("cannot close", p_path);
}

Status durable_write(const std::string &p_path, std::string_view p_data, bool p_replace) {
	if (!p_replace && exists(p_path)) {
		return Status::error(StatusCode::INVALID_STATE, "'%s' exists and is never overwritten", p_path.c_str());
	}
	const std::string temporary = p_path + ".tmp";
	const std::wstring wide_temporary = widen(temporary);
	{
		FileHandle file(CreateFileW(wide_temporary.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_ALWAYS,
				FILE_ATTRIBUTE_NORMAL, nullptr));
		if (!file.valid()) {
			return io_error("cannot create", temporary);
		}
		Status status = write_all(file.get(), p_data, temporary);
		if (!status.ok()) {
			file.close();
			DeleteFileW(wide_temporary.c_str());
			return status;
		}
		if (!FlushFileBuffers(file.get()) || !file.close()) {
			Status failed = io_error("cannot sync", temporary);
			DeleteFileW(wide_temporary.c_str());
			return failed;
		}
	}
	// WRITE_THROUGH: returns once the rename is on disk (the folder's fsync on POSIX).
	if (!MoveFileExW(wide_temporary.c_str(), widen(p_path).c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) {
		Status failed = io_error("cannot rename into", p_path);
		DeleteFileW(wide_temporary.c_str());
		return failed;
	}
	return Status::success();
}

Status make_directories(const std::string &p_path) {
	if (p_path.empty()) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "empty folder path");
	}
	size_t position = 0;
	while (position != std::string::npos) {
		position = p_path.find_first_of("/\\", position + 1);
		const std::string partial = p_path.substr(0, position);
		// "C:" (a drive) and "//server" are not folders to create.
		if (partial.empty() || partial.back() == ':' || exists(partial)) {
			continue;
		}
		if (!CreateDirectoryW(widen(partial).c_str(), nullptr) && GetLastError() != ERROR_ALREADY_EXISTS) {
			return io_error("cannot create folder", partial);
		}
	}
	return Status::success();
}

Status check_complete_lines(const std::string &p_path, bool &r_complete) {
	FileHandle file(CreateFileW(widen(p_path).c_str(), GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE, nullptr,
			OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, nullptr));
	if (!file.valid()) {
		return io_error("cannot open", p_path);
	}
	LARGE_INTEGER size;
	if (!GetFileSizeEx(file.get(), &size)) {
		return io_error("cannot read", p_path);
	}
	if (size.QuadPart == 0) {
		r_complete = true;
		return Status::success();
	}
	LARGE_INTEGER last_position;
	last_position.QuadPart = size.QuadPart - 1;
	char last = 0;
	DWORD read = 0;
	if (!SetFilePointerEx(file.get(), last_position, nullptr, FILE_BEGIN) ||
			!ReadFile(file.get(), &last, 1, &read, nullptr) || read != 1) {
		return io_error("cannot read", p_path);
	}
	r_complete = last == '\n';
	return Status::success();
}

} // namespace haptics
