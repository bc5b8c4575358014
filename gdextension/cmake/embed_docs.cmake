# Writes OUTPUT, a C++ source holding every doc_classes/*.xml under DOC_DIR as a string, which
# the library hands to the editor's help at start-up (godot-cpp-template does the same with
# its doc_data.gen.cpp). Run by the build whenever an XML file changes.
file(GLOB doc_files "${DOC_DIR}/*.xml")
list(SORT doc_files)
set(content "// Generated from gdextension/doc_classes by cmake/embed_docs.cmake: do not edit.\n")
string(APPEND content "#include \"binding/doc_data.h\"\n\nnamespace haptics::binding {\n\n")
string(APPEND content "const char *const DOC_CLASSES[] = {\n")
foreach(doc_file IN LISTS doc_files)
  file(READ "${doc_file}" xml)
  string(APPEND content "\tR\"haptics_doc(${xml})haptics_doc\",\n")
endforeach()
string(APPEND content "};\n\nconst size_t DOC_CLASS_COUNT = sizeof(DOC_CLASSES) / sizeof(DOC_CLASSES[0]);\n\n")
string(APPEND content "} // namespace haptics::binding\n")
file(WRITE "${OUTPUT}" "${content}")
