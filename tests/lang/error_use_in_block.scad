// use <...> inside braces is a syntax error in 2021.01: its grammar has it at
// a file's top level only.
echo(1);
module m() {
    use <lib/helpers.scad>
}
