#include "devices/dynamic_library.h"

#include <cstdio>
#include <string>

#include <windows.h>

namespace haptics {

namespace {

std::wstring widen(const char *p_utf8) {
	const int length = MultiByteToWideChar(CP_UTF8, 0, p_utf8, -1, nullptr, 0);
	std::wstring wide(static_cast<size_t>(length > 0 ? length : 1), L'\0');
	MultiByteToWideChar(CP_UTF8, 0, p_utf8, -1, wide.data(), length);
	return wide;
}

// Whether the file exists where LoadLibrary would look: the path itself when it names a
// folder, else the search path (SearchPathW follows the same order for a bare name).
bool file_found(const std::wstring &p_path) {
	if (p_path.find_first_of(L"/\\") != std::wstring::npos) {
		return GetFileAttributesW(p_path.c_str()) != INVALID_FILE_ATTRIBUTES;
	}
	wchar_t found[MAX_PATH];
	return SearchPathW(nullptr, p_path.c_str(), nullptr, MAX_PATH, found, nullptr) != 0;
}

} // namespace

void *open_dynamic_library(const char *p_path, bool &r_missing, char *r_error, size_t p_capacity) {
	const std::wstring path = widen(p_path);
	// No error dialog box for a missing dependency: the error comes back to us instead.
	const UINT previous_mode = SetErrorMode(SEM_FAILCRITICALERRORS | SEM_NOOPENFILEERRORBOX);
	HMODULE module = LoadLibraryW(path.c_str());
	const DWORD code = GetLastError();
	SetErrorMode(previous_mode);
	if (module != nullptr) {
		return reinterpret_cast<void *>(module);
	}
	// ERROR_MOD_NOT_FOUND also means a dependency of a file that is there: tell them apart.
	r_missing = !file_found(path);
	char text[200] = {};
	DWORD length = FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr, code, 0, text,
			sizeof(text), nullptr);
	while (length > 0 && (text[length - 1] == '\n' || text[length - 1] == '\r' || text[length - 1] == '.')) {
		text[--length] = '\0';
	}
	std::snprintf(r_error, p_capacity, "%s (Windows error %lu)", length > 0 ? text : "LoadLibrary failed",
			static_cast<unsigned long>(code));
	return nullptr;
}

void *dynamic_library_symbol(void *p_handle, const char *p_name) {
	return reinterpret_cast<void *>(GetProcAddress(static_cast<HMODULE>(p_handle), p_name));
}

void close_dynamic_library(void *p_handle) {
	FreeLibrary(static_cast<HMODULE>(p_handle));
}

void pin_loaded_library(const char *p_name) {
	HMODULE module = nullptr;
	GetModuleHandleExA(GET_MODULE_HANDLE_EX_FLAG_PIN, p_name, &module);
}

} // namespace haptics
