"""The run machinery: where jobs run, resume, the spool, signals, memory and threads."""
