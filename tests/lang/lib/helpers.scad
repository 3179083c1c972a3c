helper_value = 42;
function twice(x) = 2 * x;
module show_helper() echo("helper module", helper_value);
echo("helpers top level");
