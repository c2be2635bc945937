# Writes the man page rays.1 from the program's own help (`rays --help`, `rays render --help`):
#   cmake -DRAYS=path/to/rays -DOUT=path/to/rays.1 -P cmake/man_page.cmake
# Run by `cmake --install` (CMakeLists.txt), so the page always matches the installed binary.
foreach(var RAYS OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "man_page.cmake needs -D${var}=...")
  endif()
endforeach()
execute_process(COMMAND "${RAYS}" --version OUTPUT_VARIABLE version OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc1)
execute_process(COMMAND "${RAYS}" --help OUTPUT_VARIABLE help RESULT_VARIABLE rc2)
execute_process(COMMAND "${RAYS}" render --help OUTPUT_VARIABLE render_help RESULT_VARIABLE rc3)
if(NOT rc1 EQUAL 0 OR NOT rc2 EQUAL 0 OR NOT rc3 EQUAL 0)
  message(FATAL_ERROR "man_page.cmake: ${RAYS} --help failed")
endif()
# troff: a backslash is written \e, and a line may not start with . or '
function(troff_text in out)
  string(REPLACE "\\" "\\e" t "${in}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" t "${t}")
  set(${out} "${t}" PARENT_SCOPE)
endfunction()
troff_text("${help}" help)
troff_text("${render_help}" render_help)
string(TIMESTAMP today "%Y-%m-%d" UTC)
file(WRITE "${OUT}" ".TH RAYS 1 \"${today}\" \"${version}\" \"User Commands\"
.SH NAME
rays \\- a fast ray tracer for POV-Ray scene files
.SH SYNOPSIS
.B rays render
.I SCENE.pov
.RI [ WIDTH\\ HEIGHT ]
.RB [ \\-o
.IR out.png ]
.RI [ options ]
.br
.B rays
.BI +I SCENE.pov
.BI +W 640
.BI +H 480
.RI [ POV-Ray\\ switches ]
.br
.B rays render \\-\\-scene
.I N
(a shipped scene; \\fBrays scenes\\fR lists them)
.SH DESCRIPTION
The text below is the program's own help (\\fBrays \\-\\-help\\fR and \\fBrays render \\-\\-help\\fR).
The full reference is docs/cli.md in the documentation folder (share/doc/rays).
.SH COMMANDS
.nf
${help}.fi
.SH RENDER OPTIONS
.nf
${render_help}.fi
.SH FILES
.TP
.I PREFIX/share/rays/scenes
the shipped scenes, their textures and models (\\fBrays scenes\\fR; \\fB$RAYS_SCENES\\fR overrides the folder)
.TP
.I PREFIX/share/doc/rays
README.md and the docs folder
")
