#include "binding/durable_file_binding.h"

#include "binding/log.h"
#include "storage/durable_file.h"

namespace haptics::binding {

namespace {

bool report(const char *p_method, const Status &p_status) {
	if (!p_status.ok()) {
		gd::print_error(std::string("DurableFile.") + p_method + ": " + p_status.message(), p_method,
				__FILE__, __LINE__);
	}
	return p_status.ok();
}

} // namespace

void DurableFile::bind_methods(gd::ClassBinder<DurableFile> &r_binder) {
	r_binder.bind_method("append", &DurableFile::append, { "path", "text" });
	r_binder.bind_method("write", &DurableFile::write, { "path", "text", "replace" },
			{ gd::Variant(false) });
	r_binder.bind_method("make_dirs", &DurableFile::make_dirs, { "path" });
	r_binder.bind_method("check_complete", &DurableFile::check_complete, { "path" });
}

bool DurableFile::append(const std::string &p_path, const std::string &p_text) {
	return report("append", durable_append(p_path, p_text));
}

bool DurableFile::write(const std::string &p_path, const std::string &p_text, bool p_replace) {
	return report("write", durable_write(p_path, p_text, p_replace));
}

bool DurableFile::make_dirs(const std::string &p_path) {
	return report("make_dirs", make_directories(p_path));
}

int64_t DurableFile::check_complete(const std::string &p_path) {
	bool complete = false;
	if (!report("check_complete", check_complete_lines(p_path, complete))) {
		return -1;
	}
	return complete ? 1 : 0;
}

} // namespace haptics::binding
