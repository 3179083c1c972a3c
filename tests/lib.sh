# tests/lib.sh — what the shell test scripts share: source it, then
#   check NAME COMMAND...   counts COMMAND's success, prints "FAIL NAME" else
#   summary WHAT            prints "WHAT: N passed, M failed"; 0 when none failed
passed=0
failed=0

check() { # name, condition (a command)
    local name=$1
    shift
    if "$@"; then
        passed=$((passed + 1))
    else
        echo "FAIL $name"
        failed=$((failed + 1))
    fi
}

summary() { # what
    echo "$1: $passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}
