// version, version_num, parent_module, $parent_modules
echo(version(), version_num());
module inner() echo(parent_module(0), parent_module(1), $parent_modules);
module outer() inner();
outer();
module deep(n) if (n > 0) deep(n - 1); else echo(depth = $parent_modules, top = parent_module($parent_modules - 1));
deep(3);
