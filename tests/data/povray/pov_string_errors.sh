#!/bin/sh
# Measures the string-function cases that stop POV-Ray 3.7 (a parse error ends the parse, so each
# case needs its own run). Writes pov_string_errors.txt in the format of pov_strings.txt, with
# "!MESSAGE" as the result: POV-Ray's message after "Parse Error: " (the console's 80-column line
# breaks removed), or "!abort" when povray itself aborts.
# Run in this folder:  sh pov_string_errors.sh
set -eu
out=pov_string_errors.txt
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: > "$out"

# measure KEY EXPRESSION
measure() {
    cat > "$tmp/case.pov" <<SCENE
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location -z look_at 0 }
sphere { 0, 1 }
#declare R = $2;
SCENE
    povray +I"$tmp/case.pov" +O"$tmp/case.png" +W1 +H1 -D -F -V Work_Threads=1 > "$tmp/log" 2>&1 || true
    if grep -q 'buffer overflow detected' "$tmp/log"; then
        msg=abort
    else
        # The message starts after "Parse Error: " and runs until "Fatal error in parser".
        msg=$(awk '/Parse Error: /{sub(/.*Parse Error: /, ""); on=1}
                   /^Fatal error in parser/{on=0}
                   on{printf "%s", $0}' "$tmp/log")
    fi
    [ -n "$msg" ] || msg="(no error)"
    printf '%s|!%s\n' "$1" "$msg" >> "$out"
}

measure 'substr|ABCDEFGHI|-1|1'     'substr("ABCDEFGHI", -1, 1)'
measure 'substr|ABCDEFGHI|1|-1'     'substr("ABCDEFGHI", 1, -1)'
measure 'substr|ABCDEFGHI|4|-1'     'substr("ABCDEFGHI", 4, -1)'
measure 'substr|ABCDEFGHI|9|2'      'substr("ABCDEFGHI", 9, 2)'
measure 'substr|ABCDEFGHI|10|1'     'substr("ABCDEFGHI", 10, 1)'
measure 'substr|ABCDEFGHI|11|0'     'substr("ABCDEFGHI", 11, 0)'
measure 'substr|ABCDEFGHI|1|10'     'substr("ABCDEFGHI", 1, 10)'
measure 'substr|ABCDEFGHI|0|11'     'substr("ABCDEFGHI", 0, 11)'
measure 'substr|ABCDEFGHI|2|1e10'   'substr("ABCDEFGHI", 2, 1e10)'
measure 'substr|ABCDEFGHI|1e10|1'   'substr("ABCDEFGHI", 1e10, 1)'
measure 'substr||1|1'               'substr("", 1, 1)'
measure 'substr||2|0'               'substr("", 2, 0)'
measure 'chr|-1'                    'chr(-1)'
measure 'chr|65536'                 'chr(65536)'
measure 'chr|70000.5'               'chr(70000.5)'
measure 'chr|1e10'                  'chr(1e10)'
measure 'datetime|0|'               'datetime(0, "")'
measure 'datetime|0|%Z'             'datetime(0, "%Z")'
measure 'datetime|0|%z'             'datetime(0, "%z")'
x200=$(printf '%0200d' 0 | tr 0 x)
measure "datetime|0|$x200"          "datetime(0, \"$x200\")"
measure 'datetime|0|%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A12345678' \
        'datetime(0, "%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A%A12345678")'
measure 'datetime|2921940|(default)'        'datetime(2921940)'
measure 'datetime|-219145.00001|(default)'  'datetime(-219145.00001)'
measure 'datetime|1e7|(default)'            'datetime(1e7)'
measure 'datetime|-1e6|(default)'           'datetime(-1e6)'
measure 'vstr|2|1;2|,|0|766'       'vstr(2, <1, 2>, ",", 0, 766)'
measure 'vstr|2|1;2|,|768|1'       'vstr(2, <1, 2>, ",", 768, 1)'
measure 'vstr|2|1;2|,|-768|1'      'vstr(2, <1, 2>, ",", -768, 1)'
measure 'vstr|2|1;2|,|0|1000'      'vstr(2, <1, 2>, ",", 0, 1000)'
measure 'vstr|2|1;2|,|1000000000|1' 'vstr(2, <1, 2>, ",", 1000000000, 1)'
