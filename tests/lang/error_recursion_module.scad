// Unbounded module recursion: openscad 2021.01 reports it at the module's
// definition, with 5 TRACE lines
module crash(a = 1)
{
    crash([a, 10, 10]);
}
crash();
