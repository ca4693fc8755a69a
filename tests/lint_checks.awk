# tests/lint_checks.awk: finds shell-test lines where `check DESC CMD...` is chained with && or ||
# outside quotes. The shell runs what follows the chain after check has already counted a pass,
# so that condition could never fail the suite. Prints FILE:LINE: TEXT for each; exits 1 if any.
# (Write `if A && B; then ok; else ko DESC; fi`, or `check DESC sh -c 'A && B'`.)
# Quotes are followed one level deep: a double-quoted $(...) holding quotes reads as two strings
# with the command's words between them, which is enough for the lines of tests/*.sh.
$1 == "check" {
    line = $0
    while (line ~ /\\$/ && (getline more) > 0) line = substr(line, 1, length(line) - 1) " " more
    q = ""; out = ""
    for (i = 1; i <= length(line); i++) {
        c = substr(line, i, 1)
        if (q == "" && c == "\\") { i++; continue }
        if (q == "\"" && c == "\\") { i++; continue }
        if (q == "") { if (c == "'" || c == "\"") q = c; else out = out c }
        else if (c == q) q = ""
    }
    if (out ~ /&&|\|\|/) { print FILENAME ":" FNR ": " $0; bad = 1 }
}
END { exit bad }
