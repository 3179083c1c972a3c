// let binds sequentially; later bindings see earlier ones
echo(let(a = 1, b = a + 1, c = b * 2) [a, b, c]);
echo(let(a = 1) let(a = a + 10) a);
echo([for (i = [1 : 3]) let(j = i * 2, k = j + i) k]);
x = 5;
echo(let(x = x * 2) x, x);
let(p = 2, q = p * p) echo(p = p, q = q);
