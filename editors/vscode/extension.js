// The VS Code side of scoopc's language support: starts `scoopc lsp` (found on PATH, or the command
// set in `scoopc.server.path`) and connects it to Eiffel documents. Highlighting, brackets and
// snippets are declarative (package.json); everything that needs the checker comes from the server.
"use strict";

const vscode = require("vscode");
const { LanguageClient, TransportKind } = require("vscode-languageclient/node");

let client;

function serverOptions() {
  const settings = vscode.workspace.getConfiguration("scoopc");
  const command = settings.get("server.path") || "scoopc";
  const args = ["lsp", ...settings.get("server.extraArgs", [])];
  return { command, args, transport: TransportKind.stdio };
}

async function start(context) {
  client = new LanguageClient(
    "scoopc",
    "scoopc",
    serverOptions(),
    {
      documentSelector: [{ scheme: "file", language: "eiffel" }],
      synchronize: { fileEvents: vscode.workspace.createFileSystemWatcher("**/*.{e,ecf}") },
    }
  );
  try {
    await client.start();
  } catch (error) {
    const command = serverOptions().command;
    vscode.window.showErrorMessage(
      `scoopc: could not start \`${command} lsp\` (${error.message}). Install scoopc ` +
        "(pip install scoopc) or set `scoopc.server.path` to its command."
    );
  }
}

async function activate(context) {
  context.subscriptions.push(
    vscode.commands.registerCommand("scoopc.restartServer", async () => {
      if (client) {
        await client.stop();
      }
      await start(context);
    })
  );
  await start(context);
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
