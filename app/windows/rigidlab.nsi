; SPDX-License-Identifier: GPL-3.0-or-later
; The Windows installer, in English and Czech: makensis (NSIS 3) on the installed folder.
; ./lab package-windows runs it as
;   makensis -DSTAGE=DIR -DGENERATED=DIR -DOUTFILE=FILE rigidlab.nsi
; STAGE: the folder `cmake --install` filled (bin/, plugins/, translations/, share/);
; GENERATED: version.nsh (app/windows/CMakeLists.txt) and the lists of the files to install
; and to remove (nsis_file_lists.py), so that the uninstaller removes exactly what was installed.
;
; Without administrator rights it installs for the user alone, into
; %LOCALAPPDATA%\Programs\RigidLab, and needs no UAC prompt; run as administrator, for everybody,
; into Program Files. /S installs silently (with the default parts); /CurrentUser or /AllUsers
; choose the mode; /NODESKTOP leaves out the desktop shortcut. The user's own lessons and
; scenes (%LOCALAPPDATA%\rigidlab, Documents) and settings (%APPDATA%\RigidLab) are the user's:
; the uninstaller leaves them.

; A 64-bit installer for a 64-bit program: Windows 10 and 11 on x64 (and Wine's wine64 alone).
Target amd64-unicode
SetCompressor /SOLID lzma
!addincludedir "${GENERATED}"
!include version.nsh

!define APP_NAME "RigidLab"
!define APP_EXE "bin\rigidlab.exe"
!define REG_APP "Software\RigidLab"
!define REG_UNINSTALL "Software\Microsoft\Windows\CurrentVersion\Uninstall\RigidLab"
!define LESSON_CLASS "RigidLab.Lesson"
!define SCENE_CLASS "RigidLab.Scene"

Name "${APP_NAME}"
OutFile "${OUTFILE}"
BrandingText "${APP_NAME} ${VERSION}"

; Per user without administrator rights, for all users when run as one.
!define MULTIUSER_EXECUTIONLEVEL Highest
!define MULTIUSER_MUI
!define MULTIUSER_INSTALLMODE_COMMANDLINE
!define MULTIUSER_INSTALLMODE_INSTDIR "${APP_NAME}"
!define MULTIUSER_USE_PROGRAMFILES64
!define MULTIUSER_INSTALLMODE_DEFAULT_REGISTRY_KEY "${REG_APP}"
!define MULTIUSER_INSTALLMODE_DEFAULT_REGISTRY_VALUENAME "InstallMode"
!define MULTIUSER_INSTALLMODE_INSTDIR_REGISTRY_KEY "${REG_APP}"
!define MULTIUSER_INSTALLMODE_INSTDIR_REGISTRY_VALUENAME "InstallDir"
!include MultiUser.nsh
!include MUI2.nsh
!include LogicLib.nsh
!include FileFunc.nsh

!define MUI_ICON "${STAGE}\share\rigidlab\rigidlab.ico"
!define MUI_UNICON "${STAGE}\share\rigidlab\rigidlab.ico"
!define MUI_ABORTWARNING
!define MUI_COMPONENTSPAGE_NODESC

!insertmacro MUI_PAGE_WELCOME
!insertmacro MUI_PAGE_LICENSE "${STAGE}\share\doc\rigidlab\LICENSE"
!insertmacro MULTIUSER_PAGE_INSTALLMODE
!insertmacro MUI_PAGE_COMPONENTS
!insertmacro MUI_PAGE_DIRECTORY
!insertmacro MUI_PAGE_INSTFILES
!define MUI_FINISHPAGE_RUN "$INSTDIR\${APP_EXE}"
!insertmacro MUI_PAGE_FINISH

!insertmacro MUI_UNPAGE_CONFIRM
!insertmacro MUI_UNPAGE_INSTFILES

; The first is the default; Windows' own language chooses among them.
!insertmacro MUI_LANGUAGE "English"
!insertmacro MUI_LANGUAGE "Czech"

LangString SecProgram ${LANG_ENGLISH} "RigidLab (the lab, rigidlab-cli, lessons and scenes)"
LangString SecProgram ${LANG_CZECH} "RigidLab (laboratoř, rigidlab-cli, lekce a scény)"
LangString SecDesktop ${LANG_ENGLISH} "Desktop shortcut"
LangString SecDesktop ${LANG_CZECH} "Zástupce na ploše"
LangString SecOpenWith ${LANG_ENGLISH} "Offer RigidLab in 'Open with' for scene files (.json)"
LangString SecOpenWith ${LANG_CZECH} "Nabízet RigidLab v nabídce „Otevřít v programu“ pro scény (.json)"
LangString LessonType ${LANG_ENGLISH} "RigidLab lesson"
LangString LessonType ${LANG_CZECH} "Lekce RigidLab"
LangString SceneType ${LANG_ENGLISH} "RigidLab scene"
LangString SceneType ${LANG_CZECH} "Scéna RigidLab"
LangString AppComment ${LANG_ENGLISH} "Colliding bodies, live energy and momentum plots, and guided lessons"
LangString AppComment ${LANG_CZECH} "Srážky těles, živé grafy energie a hybnosti a řízené lekce"

VIProductVersion "${VERSION_MAJOR}.${VERSION_MINOR}.0.0"
VIAddVersionKey /LANG=${LANG_ENGLISH} "ProductName" "${APP_NAME}"
VIAddVersionKey /LANG=${LANG_ENGLISH} "FileDescription" "${APP_NAME} ${VERSION} setup"
VIAddVersionKey /LANG=${LANG_ENGLISH} "FileVersion" "${VERSION}"
VIAddVersionKey /LANG=${LANG_ENGLISH} "ProductVersion" "${VERSION}"
VIAddVersionKey /LANG=${LANG_ENGLISH} "LegalCopyright" "GPL-3.0-or-later"

Section "!$(SecProgram)" SecProgram
    SectionIn RO
    SetOutPath "$INSTDIR"
    !include install_files.nsh
    WriteUninstaller "$INSTDIR\uninstall.exe"

    WriteRegStr SHCTX "${REG_APP}" "InstallDir" "$INSTDIR"
    WriteRegStr SHCTX "${REG_APP}" "InstallMode" "$MultiUser.InstallMode"

    ; Apps & features (Programs and Features).
    WriteRegStr SHCTX "${REG_UNINSTALL}" "DisplayName" "${APP_NAME}"
    WriteRegStr SHCTX "${REG_UNINSTALL}" "DisplayVersion" "${VERSION}"
    WriteRegStr SHCTX "${REG_UNINSTALL}" "Publisher" "The RigidLab developers"
    WriteRegStr SHCTX "${REG_UNINSTALL}" "DisplayIcon" "$INSTDIR\${APP_EXE},0"
    WriteRegStr SHCTX "${REG_UNINSTALL}" "InstallLocation" "$INSTDIR"
    WriteRegStr SHCTX "${REG_UNINSTALL}" "UninstallString" '"$INSTDIR\uninstall.exe" /$MultiUser.InstallMode'
    WriteRegStr SHCTX "${REG_UNINSTALL}" "QuietUninstallString" '"$INSTDIR\uninstall.exe" /$MultiUser.InstallMode /S'
    WriteRegDWORD SHCTX "${REG_UNINSTALL}" "NoModify" 1
    WriteRegDWORD SHCTX "${REG_UNINSTALL}" "NoRepair" 1
    ${GetSize} "$INSTDIR" "/S=0K" $0 $1 $2
    WriteRegDWORD SHCTX "${REG_UNINSTALL}" "EstimatedSize" $0

    ; The Start menu (SetShellVarContext, set by the install mode, picks the user's or everybody's).
    CreateShortcut "$SMPROGRAMS\${APP_NAME}.lnk" "$INSTDIR\${APP_EXE}" "" "$INSTDIR\${APP_EXE}" 0 \
        SW_SHOWNORMAL "" "$(AppComment)"

    ; .rlesson files open in the lab on a double click.
    WriteRegStr SHCTX "Software\Classes\.rlesson" "" "${LESSON_CLASS}"
    WriteRegStr SHCTX "Software\Classes\${LESSON_CLASS}" "" "$(LessonType)"
    WriteRegStr SHCTX "Software\Classes\${LESSON_CLASS}\DefaultIcon" "" "$INSTDIR\${APP_EXE},0"
    WriteRegStr SHCTX "Software\Classes\${LESSON_CLASS}\shell\open\command" "" '"$INSTDIR\${APP_EXE}" "%1"'
    ; The lab as an application Windows can offer for files.
    WriteRegStr SHCTX "Software\Classes\Applications\rigidlab.exe" "FriendlyAppName" "${APP_NAME}"
    WriteRegStr SHCTX "Software\Classes\Applications\rigidlab.exe\shell\open\command" "" '"$INSTDIR\${APP_EXE}" "%1"'
    WriteRegStr SHCTX "Software\Classes\Applications\rigidlab.exe\SupportedTypes" ".rlesson" ""
    System::Call 'shell32::SHChangeNotify(i 0x08000000, i 0, p 0, p 0)' ; SHCNE_ASSOCCHANGED
SectionEnd

Section "$(SecDesktop)" SecDesktop
    CreateShortcut "$DESKTOP\${APP_NAME}.lnk" "$INSTDIR\${APP_EXE}" "" "$INSTDIR\${APP_EXE}" 0 \
        SW_SHOWNORMAL "" "$(AppComment)"
SectionEnd

; Scenes are JSON files, which belong to editors: the lab is offered in "Open with", never made
; their default.
Section "$(SecOpenWith)" SecOpenWith
    WriteRegStr SHCTX "Software\Classes\${SCENE_CLASS}" "" "$(SceneType)"
    WriteRegStr SHCTX "Software\Classes\${SCENE_CLASS}\DefaultIcon" "" "$INSTDIR\${APP_EXE},0"
    WriteRegStr SHCTX "Software\Classes\${SCENE_CLASS}\shell\open\command" "" '"$INSTDIR\${APP_EXE}" "%1"'
    WriteRegStr SHCTX "Software\Classes\.json\OpenWithProgids" "${SCENE_CLASS}" ""
    WriteRegStr SHCTX "Software\Classes\Applications\rigidlab.exe\SupportedTypes" ".json" ""
    System::Call 'shell32::SHChangeNotify(i 0x08000000, i 0, p 0, p 0)'
SectionEnd

Function .onInit
    SetRegView 64
    !insertmacro MULTIUSER_INIT
    ${GetParameters} $R0
    ClearErrors
    ${GetOptions} $R0 "/NODESKTOP" $R1
    ${IfNot} ${Errors}
        SectionSetFlags ${SecDesktop} 0
    ${EndIf}
FunctionEnd

Function un.onInit
    SetRegView 64
    !insertmacro MULTIUSER_UNINIT
FunctionEnd

Section "Uninstall"
    ; What was installed, file by file, then its folders if they are empty: anything the
    ; teacher put into the installation folder stays, with the folders that hold it.
    !include uninstall_files.nsh
    Delete "$INSTDIR\uninstall.exe"
    RMDir "$INSTDIR"

    Delete "$SMPROGRAMS\${APP_NAME}.lnk"
    Delete "$DESKTOP\${APP_NAME}.lnk"

    ; The associations, where they are still the lab's.
    ReadRegStr $0 SHCTX "Software\Classes\.rlesson" ""
    ${If} $0 == "${LESSON_CLASS}"
        DeleteRegValue SHCTX "Software\Classes\.rlesson" ""
        DeleteRegKey /ifempty SHCTX "Software\Classes\.rlesson"
    ${EndIf}
    DeleteRegKey SHCTX "Software\Classes\${LESSON_CLASS}"
    DeleteRegKey SHCTX "Software\Classes\${SCENE_CLASS}"
    DeleteRegValue SHCTX "Software\Classes\.json\OpenWithProgids" "${SCENE_CLASS}"
    DeleteRegKey /ifempty SHCTX "Software\Classes\.json\OpenWithProgids"
    DeleteRegKey SHCTX "Software\Classes\Applications\rigidlab.exe"
    DeleteRegKey SHCTX "${REG_UNINSTALL}"
    DeleteRegValue SHCTX "${REG_APP}" "InstallDir"
    DeleteRegValue SHCTX "${REG_APP}" "InstallMode"
    DeleteRegKey /ifempty SHCTX "${REG_APP}"
    System::Call 'shell32::SHChangeNotify(i 0x08000000, i 0, p 0, p 0)'
SectionEnd
