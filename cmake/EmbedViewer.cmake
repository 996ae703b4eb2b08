# Writes the web viewer's vendored scripts (third_party/three/*.js) into one C++ file as raw
# string literals, looked up by file name (export/viewer_assets.h). Each script is cut into
# pieces under 60,000 characters, joined at run time: ISO C++ promises string literals of
# 65,536 characters only, and three.module.min.js is ten times that.
file(GLOB scripts "${SCRIPT_DIR}/*.js")
list(SORT scripts)
set(body "// Generated from third_party/three/*.js by cmake/EmbedViewer.cmake. Do not edit.\n")
string(APPEND body "#include \"export/viewer_assets.h\"\n\nnamespace systole::exporter {\n\n")
string(APPEND body "const std::vector<EmbeddedScript>& embedded_scripts() {\n")
string(APPEND body "  static const std::vector<EmbeddedScript> scripts = [] {\n")
string(APPEND body "    std::vector<EmbeddedScript> all;\n")
foreach(path ${scripts})
  get_filename_component(name "${path}" NAME)
  file(READ "${path}" text)
  string(LENGTH "${text}" length)
  string(APPEND body "    all.push_back({\"${name}\", std::string()});\n")
  set(offset 0)
  while(offset LESS length)
    string(SUBSTRING "${text}" ${offset} 60000 piece)
    string(APPEND body "    all.back().text += R\"SYSTOLE_JS(${piece})SYSTOLE_JS\";\n")
    math(EXPR offset "${offset} + 60000")
  endwhile()
endforeach()
string(APPEND body "    return all;\n  }();\n  return scripts;\n}\n\n}  // namespace systole::exporter\n")
file(WRITE "${OUTPUT}.tmp" "${body}")
# Only touch the output when it changed, so an unchanged script set rebuilds nothing.
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
