extends DurableWriter
## [DurableWriter] on the native library's [code]DurableFile[/code]: the one script that
## names it, loaded by [method DurableWriter.open] only when the class exists.

var _file: DurableFile = DurableFile.new()


func append(path: String, text: String) -> bool:
	return _file.append(path, text)


func write(path: String, text: String, replace: bool) -> bool:
	return _file.write(path, text, replace)


func make_dirs(path: String) -> bool:
	return _file.make_dirs(path)


func check_complete(path: String) -> int:
	return _file.check_complete(path)
