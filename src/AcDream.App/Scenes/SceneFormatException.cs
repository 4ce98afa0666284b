namespace AcDream.App.Scenes;

/// <summary>A scene file that cannot be used; the message names the file, the field and the value.</summary>
internal sealed class SceneFormatException(string message) : Exception(message);
