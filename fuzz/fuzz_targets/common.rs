//! What every target checks of a load: it returns (no panic: libFuzzer reports those), and an
//! error is one line that names the file.

use aokit::scene::{Scene, SceneError};

pub fn check(name: &str, result: Result<Scene, SceneError>) -> Result<Scene, String> {
    result.map_err(|e| {
        let message = e.to_string();
        assert!(!message.contains(['\n', '\r']), "error message is not one line: {message:?}");
        assert!(message.contains(name), "error message does not name the file: {message:?}");
        message
    })
}
