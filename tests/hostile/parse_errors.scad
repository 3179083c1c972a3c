cube(;
sphere(1;
module;
function f(;
a = ;
if
for () ;
let () ;
}}}}
]]]]
))))
