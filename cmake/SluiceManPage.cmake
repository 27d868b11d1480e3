# Writes OUT, the sluice(1) man page, from the command's own help texts
# (`SLUICE --help` and `SLUICE COMMAND --help` for each of COMMANDS), so that
# the page says what the program says. Run at build time.
function(roff_escape in out)
  string(REPLACE "\\" "\\e" t "${in}")
  string(REPLACE "-" "\\-" t "${t}")
  # a line starting with . or ' would be a request
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" t "${t}")
  set(${out} "${t}" PARENT_SCOPE)
endfunction()

execute_process(COMMAND "${SLUICE}" --help OUTPUT_VARIABLE usage RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SLUICE} --help failed")
endif()
execute_process(COMMAND "${SLUICE}" version OUTPUT_VARIABLE version_text)
string(REGEX MATCH "sluice ([^\n]*)" _ "${version_text}")
set(version "${CMAKE_MATCH_1}")

set(page ".TH SLUICE 1 \"\" \"sluice ${version}\" \"User Commands\"\n")
string(APPEND page ".SH NAME\nsluice \\- simulation of solid\\-liquid mixtures with pluggable closures\n")
string(APPEND page ".SH SYNOPSIS\n.B sluice\n.I command\n[\\fIoptions\\fR]\n")
string(APPEND page ".SH DESCRIPTION\n"
  "sluice simulates solid\\-liquid mixtures (settling suspensions, fluidised and liquefied beds, yield\\-stress "
  "slurries, suspensions in rotating vessels) from a scene file in INI format. Every constitutive law is a "
  "closure: a shared object chosen by name in the scene. The commands and their options follow, as "
  "\\fBsluice\\fR \\fIcommand\\fR \\fB\\-\\-help\\fR prints them.\n")
roff_escape("${usage}" u)
string(APPEND page ".PP\n.nf\n${u}.fi\n.SH COMMANDS\n")
foreach(cmd IN LISTS COMMANDS)
  execute_process(COMMAND "${SLUICE}" ${cmd} --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${SLUICE} ${cmd} --help failed")
  endif()
  roff_escape("${help}" h)
  string(APPEND page ".SS ${cmd}\n.nf\n${h}.fi\n")
endforeach()
string(APPEND page ".SH EXIT STATUS\n"
  "0 success; 1 the run failed (the last good state is saved); 2 bad usage or bad input (nothing is written).\n"
  ".SH ENVIRONMENT\n.TP\n.B SLUICE_PLUGIN_PATH\n"
  "Folders searched for closure libraries (colon\\-separated), after the scene's [plugins] path and before "
  "sluice's own plugin folder.\n.TP\n.B SLUICE_PROGRESS\n"
  "0: no progress; 1: a line redrawn in place; lines: a line every interval (the default when stderr is not a "
  "terminal).\n.TP\n.B SLUICE_PROGRESS_EVERY\nSeconds between the lines of the log (default 10).\n.TP\n.B SLUICE_STEP_TRACE\n"
  "1: print every decision of the adaptive step controller on stderr.\n"
  ".SH FILES\n.TP\n.I share/sluice/configs\nThe shipped scenes and benchmark studies.\n.TP\n"
  ".I share/doc/sluice\nThe documentation: the scene format, the models, the closures, verification and "
  "benchmarks.\n"
  ".SH SEE ALSO\n\\fBpkg\\-config\\fR(1) (the embedding API: pkg\\-config sluice)\n")
file(WRITE "${OUT}" "${page}")
