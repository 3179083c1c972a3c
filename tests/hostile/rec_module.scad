module f() f();
f();
