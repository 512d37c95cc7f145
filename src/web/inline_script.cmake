# The single-file page (src/web/CMakeLists.txt): writes OUTPUT, the page SHELL with its
# <script async src="index.js"></script> replaced by the text of SCRIPT, inline.
#   cmake -DSHELL=shell.html -DSCRIPT=raycam.js -DOUTPUT=raycam.html -P inline_script.cmake
set(tag "<script async src=\"index.js\"></script>")
file(READ "${SHELL}" page)
file(READ "${SCRIPT}" code)
string(FIND "${page}" "${tag}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${SHELL} has no ${tag} to replace")
endif()
# Inline, the script's text must not close its own <script> element.
string(FIND "${code}" "</script" closing)
if(NOT closing EQUAL -1)
  message(FATAL_ERROR "${SCRIPT} holds \"</script\": it cannot be inlined as it is")
endif()
string(REPLACE "${tag}" "<script>\n${code}\n</script>" page "${page}")
file(WRITE "${OUTPUT}" "${page}")
