// Writes that survive a crash or a kill at any moment: the study runner's guarantee that a
// completed record is on disk before the participant moves on. Godot's FileAccess flushes
// to the kernel but never fsyncs, so a power cut could still lose "saved" records.
//
// One implementation per platform: durable_file_posix.cpp (open/write/fsync/rename, then the
// folder fsynced) and durable_file_windows.cpp (FlushFileBuffers and MoveFileExW with
// MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH; NTFS journals its folders, which cannot
// be flushed). Paths are native file-system paths, UTF-8; on Windows both slashes separate.
#pragma once

#include <string>
#include <string_view>

#include "core/base/status.h"

namespace haptics {

// Appends p_data in one write and fsyncs the file (and, when the file is new, its folder)
// before returning. The file is created if missing; existing bytes are never touched.
Status durable_append(const std::string &p_path, std::string_view p_data);

// Writes p_data to p_path through a temporary file in the same folder, fsync, rename and
// folder fsync, so readers see either the old or the new file, never a mix. With
// p_replace false an existing file is an error and is left as it is.
Status durable_write(const std::string &p_path, std::string_view p_data, bool p_replace);

// mkdir -p; existing folders are fine.
Status make_directories(const std::string &p_path);

// Whether p_path's last byte is '\n' (or the file is empty): a record cut by a crash
// leaves a final line without one. Missing file: error.
Status check_complete_lines(const std::string &p_path, bool &r_complete);

} // namespace haptics
