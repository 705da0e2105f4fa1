//! Never built: this package only fetches Bevy 0.20's sources (see Cargo.toml).
