function a(x) = b(x) + 1;
function b(x) = a(x) * 2;
echo(a(1));
