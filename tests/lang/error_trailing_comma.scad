// A trailing comma ends no call: a syntax error in 2021.01
echo("string",);
