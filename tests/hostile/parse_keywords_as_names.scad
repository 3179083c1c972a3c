module module() cube();
function function() = 1;
if = 3;
for = [1];
echo(if, for);
