// Tokenizes every class of the repository's samples/ and stdlib/ with the grammar, as VS Code
// does, and fails when a token is marked invalid or when a file ends inside a string or a
// comment (a begin/end rule that ran away). Run by `npm run test:samples`.
"use strict";

const fs = require("fs");
const path = require("path");
const oniguruma = require("vscode-oniguruma");
const textmate = require("vscode-textmate");

const root = path.resolve(__dirname, "..", "..", "..");

function classes(folder) {
  const found = [];
  for (const entry of fs.readdirSync(folder, { withFileTypes: true })) {
    const where = path.join(folder, entry.name);
    if (entry.isDirectory()) found.push(...classes(where));
    else if (entry.name.endsWith(".e")) found.push(where);
  }
  return found;
}

async function grammar() {
  const wasm = fs.readFileSync(require.resolve("vscode-oniguruma/release/onig.wasm"));
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const registry = new textmate.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (text) => new oniguruma.OnigString(text),
    }),
    loadGrammar: async () =>
      textmate.parseRawGrammar(
        fs.readFileSync(path.join(__dirname, "..", "syntaxes", "eiffel.tmLanguage.json"), "utf8"),
        "eiffel.tmLanguage.json"
      ),
  });
  return registry.loadGrammar("source.eiffel");
}

function problems(eiffel, file) {
  const found = [];
  let stack = textmate.INITIAL;
  const lines = fs.readFileSync(file, "utf8").split(/\r?\n/);
  lines.forEach((line, index) => {
    const result = eiffel.tokenizeLine(line, stack);
    for (const token of result.tokens) {
      if (token.scopes.some((scope) => scope.startsWith("invalid"))) {
        const text = line.slice(token.startIndex, token.endIndex);
        found.push(`${file}:${index + 1}:${token.startIndex + 1}: invalid token ${JSON.stringify(text)}`);
      }
    }
    stack = result.ruleStack;
  });
  if (stack.depth > 1) {
    found.push(`${file}: ends inside a string or another multi-line construct`);
  }
  return found;
}

(async () => {
  const eiffel = await grammar();
  const files = ["samples", "stdlib"].flatMap((folder) => classes(path.join(root, folder)));
  const found = files.flatMap((file) => problems(eiffel, file));
  found.forEach((line) => console.error(line));
  console.log(`${files.length} classes tokenized, ${found.length} problems`);
  process.exit(found.length === 0 && files.length > 0 ? 0 : 1);
})();
