# Sourced by scripts/check-course-labs.sh.
# Expectations: a folder's check-course-lab.txt, one per line (# starts a comment):
#   cmake: -DNAME=VALUE          an option for its configure step
#   configure says: TEXT         a line the configure step must print
#   build fails                  it must not build (the configure lines still count)
#   hold the mouse at: X Y       hold the left button down there from the second second
#   run says: TEXT               a line the program must print
expectation() { # expectation FOLDER KEY -> every value given for KEY, one a line
    [[ -f $1/check-course-lab.txt ]] || return 0
    sed -n "s/^$2: *//p" "$1/check-course-lab.txt"
}
