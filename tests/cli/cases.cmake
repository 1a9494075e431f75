# cases filled in with the CLI
